"""``python -m flexshaft``: the ``flexshaft`` command (the same Typer app as the console script)."""

from flexshaft.cli import app

if __name__ == "__main__":
    app(prog_name="flexshaft")
