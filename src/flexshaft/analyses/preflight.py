"""What the analyses refuse in a schema-valid design, found before running them.

The schema bounds each number on its own; :func:`model_guards` gathers what the analyses refuse
after it has accepted a design: the checks of :func:`~flexshaft.assembly.build_model` (problem
size, support and actuator stiffness, magnet gains, the controller law) and the solves every
command starts from (the modal basis and the lowest modes at the operating speed, the static
deflection, the imbalance load cases and the response at the operating speed), each as a
:class:`~flexshaft.design.Problem` naming the fields. ``flexshaft check`` is to report them
with the thermal ones (:func:`flexshaft.thermal.preflight.thermal_guards`), so that a design it
accepts runs (issue 27: ``coil_turns = 1e5`` and 26 more designs passed ``check`` and were then
refused by every analysis).
"""

from __future__ import annotations

from typing import Any

__all__ = ["model_guards"]


def model_guards(design: Any) -> list:
    """What the analyses refuse in a schema-valid design, as a list of
    :class:`~flexshaft.design.Problem` (empty when every analysis of the model can run).

    Builds the model (:func:`~flexshaft.assembly.build_model`: its :class:`DesignError`
    problems are returned as they are, and nothing else is tried), then computes what every
    command starts from, each refused error becoming a problem naming the fields that set it:
    the modal basis and the 4 lowest modes at the operating speed (``modes``, ``campbell``,
    ``stability``, ``runup``), the static deflection under the design's loads and torque
    (strength, bearing loads, thermal), the imbalance load cases (``loads.imbalance_placement``:
    ``"worst"`` beyond its bays) and the imbalance response at the operating speed (spin-up,
    thermal). About 0.2 s on the baseline.
    """
    import warnings

    from flexshaft.analyses.eigen import reduce
    from flexshaft.analyses.modal import default_basis_size, modes
    from flexshaft.analyses.response import imbalance_response, static_response
    from flexshaft.assembly import build_model
    from flexshaft.assembly.loads import external_static_load, imbalance_loads, torque_load
    from flexshaft.design import DesignError, Problem

    try:
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # a size warning is not a refusal
            model = build_model(design)
    except DesignError as error:
        return list(error.problems)
    loads: list = []  # the imbalance load cases, once built
    checks = (
        (
            "shaft.material",
            "the modal basis of every eigen-analysis (modes, campbell, stability, runup)",
            lambda: reduce(model, default_basis_size(4)),
        ),
        (
            "design",
            "the lowest modes at the operating speed (modes, campbell, stability)",
            lambda: modes(model, model.speed, 4),
        ),
        (
            "bearings",
            "the static deflection under the design's loads and torque (strength, bearing loads, thermal)",
            lambda: static_response(model, external_static_load(model) + torque_load(model)),
        ),
        (
            "loads.imbalance_placement",
            "the imbalance load cases (spin-up, thermal, bearing loads)",
            lambda: loads.append(imbalance_loads(model)),
        ),
        (
            "operating.speed_rpm",
            "the imbalance response at the operating speed (spin-up, thermal, bearing loads)",
            lambda: imbalance_response(model, [model.speed], loads[0]),
        ),
    )
    problems: list[Problem] = []
    for path, what, run in checks:
        try:
            with warnings.catch_warnings():
                warnings.simplefilter("ignore")
                run()
        except DesignError as error:  # the design's own refusal (the "worst" placement's bays)
            problems.extend(error.problems)
            if path == "loads.imbalance_placement":
                break  # the response needs the load cases
        except ValueError as error:  # SingularSystemError and NonFiniteResultError are ValueErrors
            problems.append(Problem(path, f"{what} is refused: {error}"))
            if path in ("shaft.material", "loads.imbalance_placement"):
                break  # the modes need the basis, the response its load cases
    return problems
