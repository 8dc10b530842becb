"""The README's Python API snippet runs as printed (each result plots in one line)."""

import re
from pathlib import Path

import matplotlib

matplotlib.use("Agg")


def test_readme_api_snippet_runs(tmp_path, monkeypatch):
    import matplotlib.pyplot as plt
    from matplotlib.figure import Figure

    text = (Path(__file__).parents[1] / "README.md").read_text(encoding="utf-8")
    section = text[text.index("## Python API") :]
    code = re.search(r"```python\n(.*?)```", section, re.S).group(1)
    monkeypatch.chdir(tmp_path)
    namespace: dict = {}
    exec(compile(code, "README.md", "exec"), namespace)  # noqa: S102 - the documented snippet itself
    for name in ("m", "c", "q"):
        assert isinstance(namespace[name].plot(), Figure)
    assert (tmp_path / "campbell.nc").is_file()
    plt.close("all")
