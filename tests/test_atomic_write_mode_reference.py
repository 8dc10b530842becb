"""A file written atomically (flexshaft.files) gets the permissions ``open()`` would give it.

Reference: a file created in the same folder by Python's ``open(path, "w")``, whose mode is
0o666 less the process's umask (POSIX ``open(2)``/``umask(2)``). ``tempfile.mkstemp`` creates
its file 0o600 (Python docs, tempfile.mkstemp: "readable and writable only by the creating
user ID"), so a written design file that kept that mode would be unreadable to the rest of a
team sharing the folder. The permission bits of both files must be equal. CPU: milliseconds.
"""

from __future__ import annotations

import os
import stat
import sys

import pytest

from flexshaft.files import atomic_write, atomic_write_text


@pytest.mark.skipif(sys.platform == "win32", reason="POSIX permission bits")
def test_an_atomic_write_has_the_mode_open_gives(tmp_path):
    reference = tmp_path / "reference.toml"
    with open(reference, "w", encoding="utf-8") as handle:
        handle.write("x = 1\n")
    expected = stat.S_IMODE(os.stat(reference).st_mode)
    if expected == 0o600:  # a umask of 077: open() and mkstemp agree, nothing to tell apart
        pytest.skip("the umask makes open() create files 0600 as mkstemp does")
    for path in (atomic_write_text(tmp_path / "a.toml", "x = 1\n"), atomic_write(tmp_path / "b.nc", b"x")):
        assert stat.S_IMODE(os.stat(path).st_mode) == expected, oct(os.stat(path).st_mode)
