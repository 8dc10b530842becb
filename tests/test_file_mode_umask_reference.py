"""A file written atomically (flexshaft.files) gets the mode ``open()`` gives under the user's umask.

Reference: POSIX ``open(2)`` creates a file with the requested mode less the process's umask
(``umask(2)``); Python's ``open(path, "w")`` requests 0o666. So, derived here by hand:

* umask 077 -> 0o666 & ~0o077 = 0o600 (private: a user who keeps results to himself),
* umask 027 -> 0o640 (group may read, others nothing),
* umask 002 -> 0o664 (a shared project group may also write).

The module docstring of ``flexshaft.files`` states the rule ("as open() would create it").
Under the usual umask 022 every one of these rules gives 0o644, so the umask must be another
one to tell "the user's umask" from a fixed 0o644; the umask is read once per process, so each
case runs in a fresh interpreter started with that umask (``subprocess``'s ``umask=``). The
child first writes ``plain.json`` with plain ``open()`` -- before it imports ``flexshaft.files``,
so nothing of the module under test can have touched the umask yet -- then ``atomic.json`` with
:func:`flexshaft.files.atomic_write_text`, then ``after.json`` with plain ``open()`` again. The
atomic file's mode must equal the hand value exactly (permission bits are integers), and so must
``after.json``'s: reading the umask means setting it, and the module must put the user's umask
back (the same rule: later files of the process keep the user's mode). Where the first plain
``open()`` does not give the hand value (a folder's default ACL) there is nothing to compare and
the case is skipped; that file is written before the module is imported, so a bug of the module
cannot turn a failure into a skip.
CPU: one short interpreter per umask, about 0.1 s each.
"""

from __future__ import annotations

import os
import stat
import subprocess
import sys
from pathlib import Path

import pytest

import flexshaft.files

CHILD = """
import sys
folder = sys.argv[1]
with open(folder + "/plain.json", "w", encoding="utf-8") as handle:  # before the import
    handle.write("{}\\n")
from flexshaft.files import atomic_write_text
atomic_write_text(folder + "/atomic.json", "{}\\n")
with open(folder + "/after.json", "w", encoding="utf-8") as handle:  # the umask restored?
    handle.write("{}\\n")
"""


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX permission bits and umask")
@pytest.mark.parametrize(
    ("umask", "expected"), [(0o077, 0o600), (0o027, 0o640), (0o002, 0o664)], ids=["077", "027", "002"]
)
def test_an_atomic_write_follows_the_users_umask(tmp_path, umask, expected):
    folder = tmp_path / f"umask{umask:03o}"
    folder.mkdir()
    # the child imports this very flexshaft (the package under test, wherever it lies)
    source = str(Path(flexshaft.files.__file__).resolve().parents[1])
    path = os.pathsep.join([source, os.environ.get("PYTHONPATH", "")]).rstrip(os.pathsep)
    env = {**os.environ, "PYTHONPATH": path}
    subprocess.run([sys.executable, "-c", CHILD, str(folder)], check=True, umask=umask, env=env, timeout=60)
    plain = stat.S_IMODE(os.stat(folder / "plain.json").st_mode)
    if plain != expected:  # a default ACL of the folder overrides the umask: nothing to compare
        pytest.skip(f"open() made {oct(plain)} under umask {umask:03o} here (a default ACL?)")
    atomic = stat.S_IMODE(os.stat(folder / "atomic.json").st_mode)
    assert atomic == expected, f"atomic write made {oct(atomic)}, open() under umask {umask:03o} makes {oct(expected)}"
    after = stat.S_IMODE(os.stat(folder / "after.json").st_mode)
    assert after == expected, f"open() after the atomic write made {oct(after)}: umask {umask:03o} not restored"
