"""What every command shares: the error boundary, plain-text printing, design loading, JSON.

The error boundary (:func:`guarded`) wraps every command. A problem the user can change (a bad
design file, argument or output folder) ends with ``error: …`` on stderr and exit code 2; a
failed requirement under ``run --strict`` exits 3; anything else is an internal fault: exit 4,
a one-paragraph hint to report it, and the traceback only with ``flexshaft --debug``.

User strings (design names, component names, paths) are printed as plain text: never through
rich markup, with control characters escaped (:func:`plain`), so that ``name = "[/bold] x"``
or a name holding terminal escape sequences prints harmlessly.
"""

from __future__ import annotations

import functools
import json
import math
import os
import re
import stat
import sys
import traceback
from collections.abc import Callable
from dataclasses import dataclass
from pathlib import Path
from typing import Any, NoReturn, TypeVar

import typer

# the design layer's limit (1 MB), checked here before the file is opened as well
from flexshaft.design.reading import MAX_DESIGN_BYTES

__all__ = [
    "EXIT_INTERNAL_ERROR",
    "EXIT_REQUIREMENT_FAILED",
    "EXIT_USER_ERROR",
    "LARGEST_GAP",
    "MAX_DESIGN_BYTES",
    "LoadedDesign",
    "UserError",
    "actuator_gap",
    "at_command_end",
    "check_finite",
    "dask_client",
    "default_design",
    "design_fingerprint",
    "fail",
    "guarded",
    "is_guarded",
    "json_ready",
    "load_design_argument",
    "plain",
    "print_json",
    "refused_by_analyses",
    "settings",
]

# The rest of the package is imported inside the functions that need it: the design schema
# (pydantic, about 0.2 s), the analyses (scipy), the report and figures (matplotlib) and
# xarray are measurably heavy, and `flexshaft --help` answers in about 0.1 s without them
# (tests/test_import.py).

#: Exit code of a user error (bad design, argument or output folder).
EXIT_USER_ERROR = 2
#: Exit code of ``flexshaft run --strict`` when a requirement fails.
EXIT_REQUIREMENT_FAILED = 3
#: Exit code of an internal fault (a bug in flexshaft).
EXIT_INTERNAL_ERROR = 4


#: Where an internal fault should be reported (pyproject.toml has no project URL yet).
BUG_REPORT_TARGET = "the flexshaft issue tracker"


@dataclass
class Settings:
    """Global options of the ``flexshaft`` command (set by its callback)."""

    debug: bool = False


#: The global options of the current invocation.
settings = Settings()


class UserError(Exception):
    """A problem the user can change; printed as ``error: …`` with exit code 2."""


def fail(message: str) -> NoReturn:
    """Stop the command with a user error (exit code 2)."""
    raise UserError(message)


# ------------------------------------------------------------------------------------------------
# Plain text

# C0 and C1 controls, DEL, line/paragraph separators and the bidirectional overrides/isolates
_CONTROL = re.compile("[\x00-\x1f\x7f-\x9f\u2028\u2029\u202a-\u202e\u2066-\u2069]")


def plain(text: Any, keep_newlines: bool = False) -> str:
    """``text`` with control characters escaped (``\\x1b``, ``\\n``, ``\\u202e``).

    The result is safe to print on a terminal; print it without markup interpretation
    (``typer.echo``, or :class:`rich.text.Text`). ``keep_newlines`` keeps line breaks (for
    messages of several lines) and escapes everything else.
    """
    text = str(text)
    if keep_newlines:
        return "\n".join(plain(line) for line in text.split("\n"))
    return _CONTROL.sub(lambda match: match.group().encode("unicode_escape").decode("ascii"), text)


def _stderr(message: str) -> None:
    typer.echo(message, err=True)


# ------------------------------------------------------------------------------------------------
# The error boundary

F = TypeVar("F", bound=Callable[..., Any])

_USER_OS_ERRORS = {
    "EACCES",
    "EPERM",
    "EROFS",
    "ENOSPC",
    "EDQUOT",
    "ENOTDIR",
    "EISDIR",
    "EEXIST",
    "ENOENT",
    "ENAMETOOLONG",
    "ELOOP",
    "EMFILE",
    "ENFILE",
    "EFBIG",
}


def _loaded_class(module: str, name: str) -> type | None:
    """An exception class if its module is already imported (an error of a module never
    loaded cannot occur, and the boundary must not import the solvers)."""
    found = sys.modules.get(module)
    cls = getattr(found, name, None) if found is not None else None
    return cls if isinstance(cls, type) else None


#: The lower layers' refusals of their input (a user error, not a fault): the analyses' and
#: thermal layers' RefusedInputError (its subclasses: singular systems, non-finite results,
#: unstable responses), the optimizer's OptimizeError. Each message names the input.
_REFUSALS = (
    ("flexshaft.analyses.guards", "RefusedInputError"),
    ("flexshaft.sweep.study", "SweepError"),
    ("flexshaft.optimize.variables", "OptimizeError"),
)


def _user_message(exc: BaseException) -> str | None:
    """The message of a user error, or None for an internal fault."""
    if isinstance(exc, UserError):
        return str(exc)
    design_error = _loaded_class("flexshaft.design.io", "DesignError")
    if design_error is not None and isinstance(exc, design_error):
        source = getattr(exc, "source", "")
        return f"invalid design {source}:\n{exc}" if source and source != "<string>" else f"invalid design:\n{exc}"
    for module, name in _REFUSALS:
        refusal = _loaded_class(module, name)
        if refusal is not None and isinstance(exc, refusal):
            return str(exc)
    if isinstance(exc, OSError) and exc.errno is not None:
        import errno

        if errno.errorcode.get(exc.errno) in _USER_OS_ERRORS:
            where = f" {exc.filename}" if exc.filename is not None else ""
            return f"cannot write or read{where}: {exc.strerror}"
    if isinstance(exc, MemoryError):
        return (
            "not enough memory for this computation; reduce mesh.shaft_elements / mesh.boom_elements, "
            "the number of speeds or the study grid"
        )
    return None


def _internal_error(exc: BaseException) -> None:
    from flexshaft import __version__

    first = str(exc).strip().splitlines()[0] if str(exc).strip() else ""
    what = f"{type(exc).__name__}: {first}" if first else type(exc).__name__
    if settings.debug:
        _stderr(plain("".join(traceback.format_exception(exc)), keep_newlines=True).rstrip("\n"))
    _stderr(plain(f"internal error: {what}", keep_newlines=False))
    hint = (
        f"This is a bug in flexshaft {__version__}, not a problem with your input. Please report it at "
        f"{BUG_REPORT_TARGET} with the design file, the command line and its output with --debug "
        "(flexshaft --debug COMMAND ...)."
    )
    if settings.debug:
        hint = (
            f"This is a bug in flexshaft {__version__}. Please report it at {BUG_REPORT_TARGET} with the "
            "design file, the command line and the traceback above."
        )
    _stderr(hint)


def _quiet_broken_pipe() -> None:
    """Point stdout at /dev/null after the reader went away (``flexshaft baseline | head``)."""
    try:
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
    except (OSError, ValueError, AttributeError):
        pass


def _pass_through() -> tuple[type[BaseException], ...]:
    """Exceptions that end a command on purpose (exit codes, usage errors, Ctrl-C)."""
    kinds: list[type[BaseException]] = [typer.Exit, typer.Abort, KeyboardInterrupt]
    if isinstance(getattr(typer, "TyperException", None), type):  # typer >= 0.2x vendors click
        kinds.append(typer.TyperException)
    try:
        import click
    except ImportError:  # pragma: no cover - typer without click
        return tuple(kinds)
    return (*kinds, click.exceptions.Exit, click.exceptions.Abort, click.ClickException)


_PASS_THROUGH = _pass_through()


def _exits() -> tuple[type[BaseException], ...]:
    """The exceptions of a command that ended on purpose with its results written (exit 0, or 3
    for a failed requirement) and of a reader that went away."""
    kinds: list[type[BaseException]] = [typer.Exit, BrokenPipeError]
    try:
        import click
    except ImportError:  # pragma: no cover - typer without click
        return tuple(kinds)
    return (*kinds, click.exceptions.Exit)


_EXITS = _exits()

#: Functions called when the running command ends, with True when it completed (see
#: :func:`at_command_end`); each invocation calls and drops those it registered.
_AT_END: list[Callable[[bool], None]] = []


def at_command_end(hook: Callable[[bool], None]) -> None:
    """Call ``hook(completed)`` when the running command ends: ``completed`` is True when it
    returned or exited on purpose (``typer.Exit``: exit 0, or 3 for a failed requirement), False
    after an error or Ctrl-C. The output folders write their final marker this way
    (:mod:`flexshaft.cli.output`), after every other file."""
    _AT_END.append(hook)


def _end_command(mark: int, completed: bool) -> None:
    hooks = _AT_END[mark:]
    del _AT_END[mark:]
    for hook in hooks:
        if completed:
            hook(True)
        else:
            try:
                hook(False)
            except Exception:  # noqa: BLE001 - the command's own error is the one to report
                pass


def _warning_format(original: Callable[..., str]) -> Callable[..., str]:
    """``warnings.formatwarning`` that prints flexshaft's own warnings (problem size, resonance,
    sweep) as one plain line ``warning: …`` on stderr, without file and line (the source line
    means nothing to a user; ``--debug`` keeps the full form)."""

    def format_warning(message, category, filename, lineno, line=None) -> str:
        if not settings.debug and getattr(category, "__module__", "").startswith("flexshaft"):
            return plain(f"warning: {message}") + "\n"
        return original(message, category, filename, lineno, line)

    return format_warning


def guarded(func: F) -> F:
    """The error boundary of a command: user error → exit 2, internal fault → exit 4.

    ``typer.Exit`` (e.g. exit 3 of ``run --strict``) and click's own usage errors pass through.
    The hooks of :func:`at_command_end` run when the command ends (the output folder's final
    marker); flexshaft's warnings print as ``warning: …`` lines.
    """

    @functools.wraps(func)
    def boundary(*args: Any, **kwargs: Any) -> Any:
        import warnings

        mark = len(_AT_END)
        original_format = warnings.formatwarning
        warnings.formatwarning = _warning_format(original_format)
        try:
            try:
                value = func(*args, **kwargs)
            except _EXITS:
                _end_command(mark, True)
                raise
            except BaseException:
                _end_command(mark, False)
                raise
            _end_command(mark, True)
            return value
        except KeyboardInterrupt as exc:  # Ctrl-C: what the interrupted work kept, if it says
            for note in getattr(exc, "__notes__", ()):
                _stderr(plain(f"interrupted: {note}"))
            raise
        except _PASS_THROUGH:
            raise
        except BrokenPipeError:
            _quiet_broken_pipe()
            raise typer.Exit(code=0) from None
        except Exception as exc:  # noqa: BLE001 - the one place every failure is classified
            message = _user_message(exc)
            if message is not None:
                _stderr(plain(f"error: {message}", keep_newlines=True))
                if settings.debug:
                    _stderr(plain("".join(traceback.format_exception(exc)), keep_newlines=True).rstrip("\n"))
                raise typer.Exit(code=EXIT_USER_ERROR) from None
            _internal_error(exc)
            raise typer.Exit(code=EXIT_INTERNAL_ERROR) from None
        finally:
            warnings.formatwarning = original_format

    boundary.__flexshaft_guarded__ = True  # type: ignore[attr-defined]
    return boundary  # type: ignore[return-value]


def is_guarded(func: Callable[..., Any]) -> bool:
    """True if ``func`` is wrapped by :func:`guarded`."""
    return bool(getattr(func, "__flexshaft_guarded__", False))


# ------------------------------------------------------------------------------------------------
# Arguments


def check_finite(
    option: str,
    value: float | None,
    minimum: float | None = None,
    maximum: float | None = None,
    *,
    positive: bool = False,
    unit: str = "",
) -> float | None:
    """``value`` if it is None or finite, within [minimum, maximum] and, with ``positive``,
    above zero; else a user error, its bound in ``unit`` (the option's, e.g. ``"rpm"``)."""
    if value is None:
        return None
    if not math.isfinite(value):
        fail(f"{option}: must be a finite number (got {value})")
    if positive and not value > 0.0:
        fail(f"{option}: must be positive (got {value:g})")
    in_unit = f" {unit}" if unit else ""
    if minimum is not None and value < minimum:
        fail(f"{option}: must be >= {minimum:g}{in_unit} (got {value:g})")
    if maximum is not None and value > maximum:
        fail(f"{option}: must be <= {maximum:g}{in_unit} (got {value:g})")
    return value


#: Largest actuator gap an option takes [m]: the design schema's largest auxiliary-bearing
#: clearance (:data:`flexshaft.design.quantities.BackupGap`).
LARGEST_GAP = 0.1


def actuator_gap(gap: float | None, gap_mm: float | None) -> float | None:
    """The actuator gap [m] of ``--gap`` [m] or ``--gap-mm`` [mm] (None without either), each
    positive and at most :data:`LARGEST_GAP`; a user error for both, or out of range (a gap in
    millimetres typed as ``--gap`` is refused, not taken as metres)."""
    from flexshaft.units import m_to_mm, mm_to_m

    if gap is not None and gap_mm is not None:
        fail(f"--gap and --gap-mm: give the actuator gap once (got --gap {gap:g} m and --gap-mm {gap_mm:g} mm)")
    if gap_mm is not None:
        check_finite("--gap-mm", gap_mm, maximum=m_to_mm(LARGEST_GAP), positive=True, unit="mm")
        metres = mm_to_m(gap_mm)
        if not metres > 0.0:  # a subnormal count of millimetres is no gap in metres
            fail(f"--gap-mm: must be positive (got {gap_mm:g}, 0 m)")
        return metres
    check_finite("--gap", gap, positive=True)
    if gap is not None and gap > LARGEST_GAP:
        fail(
            f"--gap: the actuator gap in metres, at most {LARGEST_GAP:g} m, the largest auxiliary-bearing "
            f"clearance a design takes (got {gap:g}); a gap in millimetres goes in --gap-mm"
        )
    return gap


def dask_client(address: str | None) -> Any:
    """The Dask client of ``--dask ADDRESS`` (None without one): the address checked and the
    scheduler connected with a short timeout before anything is computed
    (:func:`flexshaft.sweep.dask.connect`, a user error naming ``--dask``); closed when the
    command ends."""
    if address is None:
        return None
    from flexshaft.sweep.dask import connect

    client = connect(address, name="--dask")
    at_command_end(lambda completed: client.close())
    return client


@dataclass(frozen=True)
class LoadedDesign:
    """A validated design, the text it was read from (for the report) and where it came from."""

    design: Any  # flexshaft.design.Design
    text: str | None
    source: str


def default_design(name: str | None = None) -> LoadedDesign:
    """The design of a command run without a design file: the embedded design ``name``
    (default :data:`flexshaft.design.DEFAULT_DESIGN`, the tuned final design, for every command;
    ``flexshaft compare`` sets the current driveline beside it)."""
    from flexshaft.design import DEFAULT_DESIGN, EMBEDDED_DESIGNS, embedded_design, embedded_text

    name = name or DEFAULT_DESIGN
    return LoadedDesign(
        embedded_design(name), embedded_text(name), f"embedded {name} design ({EMBEDDED_DESIGNS[name][1]})"
    )


_FILE_KINDS = (
    (stat.S_ISDIR, "is a directory, not a design file"),
    (stat.S_ISFIFO, "is a named pipe (FIFO), not a regular design file"),
    (stat.S_ISCHR, "is a character device, not a regular design file"),
    (stat.S_ISBLK, "is a block device, not a regular design file"),
    (stat.S_ISSOCK, "is a socket, not a regular design file"),
)


def _check_design_path(path: Path) -> None:
    """Refuse, before opening it, anything but a regular file of at most MAX_DESIGN_BYTES
    (a FIFO would block forever, /dev/zero read until memory runs out)."""
    from flexshaft.design import DesignError, Problem

    shown = os.fsdecode(path)

    def refuse(message: str) -> NoReturn:
        raise DesignError([Problem(shown, message)], shown)

    try:
        info = os.stat(path)
    except FileNotFoundError:
        refuse("no such design file")
    except PermissionError:
        refuse("permission denied")
    except (OSError, ValueError) as exc:
        refuse(f"cannot read the file ({getattr(exc, 'strerror', None) or exc})")
    for is_kind, message in _FILE_KINDS:
        if is_kind(info.st_mode):
            refuse(message)
    if not stat.S_ISREG(info.st_mode):
        refuse("not a regular file")
    if info.st_size > MAX_DESIGN_BYTES:
        refuse(f"{info.st_size} bytes; a design file may have at most {MAX_DESIGN_BYTES} bytes")


def load_design_argument(path: Path | None, default: str | None = None) -> LoadedDesign:
    """The design of a command's DESIGN argument (default: the embedded design ``default``, the
    tuned design unless named).

    Raises
    ------
    flexshaft.design.DesignError
        For anything but a valid design in a regular file (exit code 2 at the boundary).
    """
    if path is None:
        return default_design(default)
    from flexshaft.design import load_design

    _check_design_path(path)
    design = load_design(path)
    try:
        with open(path, "rb") as file:
            text = file.read(MAX_DESIGN_BYTES + 1).decode("utf-8-sig")
    except (OSError, UnicodeDecodeError):  # it validated a moment ago; report without the text
        text = None
    return LoadedDesign(design, text, os.fsdecode(path))


def refused_by_analyses(loaded: LoadedDesign) -> None:
    """Raise the :class:`~flexshaft.design.DesignError` of what the analyses refuse in a
    schema-valid design (:func:`flexshaft.analyses.preflight.model_guards`, then
    :func:`flexshaft.thermal.preflight.thermal_guards`, then what the verdict refuses at the
    envelope's points, :func:`flexshaft.verdict.assess.envelope_problems`), each problem naming
    its fields; return when every analysis can run. About 0.2 s on the baseline."""
    import warnings

    from flexshaft.analyses.preflight import model_guards
    from flexshaft.design import DesignError

    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # a size warning or an ill-conditioned solve is no refusal
        problems = model_guards(loaded.design)
        if not problems:
            from flexshaft.thermal.preflight import thermal_guards

            problems = thermal_guards(loaded.design)
        if not problems:
            from flexshaft.verdict.assess import envelope_problems

            problems = envelope_problems(loaded.design)
    if problems:
        raise DesignError(problems, loaded.source)


def refuse_imbalance_cases(design: Any, source: str) -> None:
    """Raise the :class:`~flexshaft.design.DesignError` of a ``"worst"`` imbalance placement
    beyond its bays (2^(bays−1) load cases, docs/limits.md), naming ``source`` (the file), before a
    command that solves the imbalance response (``runup``, ``thermal``; every study, as
    ``flexshaft check`` refuses the design) computes or makes its folder
    (:func:`flexshaft.assembly.size.check_problem_size`'s rule, its caps lifted)."""
    import math
    import warnings

    from flexshaft.assembly.size import ProblemSizeWarning, check_problem_size
    from flexshaft.resolution import SCREENING

    with warnings.catch_warnings():
        warnings.simplefilter("ignore", ProblemSizeWarning)
        inf = math.inf  # the caps lifted: only the placement's rule decides
        check_problem_size(design, "assess", SCREENING, hard_memory=inf, hard_time=inf, source=source)


def refuse_envelope_points(design: Any, source: str) -> None:
    """Raise the :class:`~flexshaft.design.DesignError` of the envelope points the verdict would
    refuse (:func:`flexshaft.verdict.assess.envelope_problems`, a few ms a point), before a
    command that judges the design makes its output folder."""
    from flexshaft.design import DesignError
    from flexshaft.verdict.assess import envelope_problems

    if problems := envelope_problems(design):
        raise DesignError(problems, source)


def design_fingerprint(design: Any) -> str:
    """SHA-256 of the validated design's values (comments and layout of the file do not count)."""
    import hashlib

    data = design.model_dump(mode="json")
    return hashlib.sha256(json.dumps(data, sort_keys=True, default=repr).encode()).hexdigest()


# ------------------------------------------------------------------------------------------------
# JSON


def json_ready(value: Any) -> Any:
    """Plain JSON data: numpy scalars and arrays as Python numbers and lists, tuples as lists,
    non-finite floats as ``None`` (strict JSON has no NaN or infinity)."""
    if isinstance(value, dict):
        return {str(k): json_ready(v) for k, v in value.items()}
    if isinstance(value, (list, tuple)):
        return [json_ready(v) for v in value]
    if isinstance(value, bool) or value is None or isinstance(value, str):
        return value
    if isinstance(value, int):
        return value
    if isinstance(value, float):
        return value if math.isfinite(value) else None
    if hasattr(value, "tolist"):  # numpy scalar or array
        return json_ready(value.tolist())
    if hasattr(value, "value") and isinstance(value.value, str):  # an Enum
        return value.value
    try:
        return json_ready(float(value))
    except (TypeError, ValueError):
        return str(value)


def print_json(data: Any) -> None:
    """Print ``data`` as strict JSON on stdout (ASCII only, so safe on any terminal)."""
    sys.stdout.write(json.dumps(json_ready(data), indent=2, allow_nan=False) + "\n")
    sys.stdout.flush()
