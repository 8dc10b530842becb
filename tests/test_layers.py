"""The package's import graph: no cycle, no arrow up the layers, no private name across modules.

Layers, bottom to top (a module may import only from its own layer or below; see
docs/architecture.md):

    0  units, resolution (grid sizes of the recipe), parallel (pools, BLAS threads, tasks),
       netcdf, files (atomic writes), plot (figures from plain arrays; matplotlib loaded lazily)
    1  design (schema and I/O: a data leaf)
    2  laminate, strength, buckling, elements (physics on plain numbers)
    3  assembly
    4  analyses
    5  thermal
    6  sweep (generic engine)
    7  verdict (evidence, checks, assess: the one recipe that judges a design)
    8  optimize, thesis, comparison, montecarlo, validation (users of the recipe and the thesis's
       studies; the published validation cases)
    9  report (HTML from results)
    10 cli, explore (the browser explorer: it runs a design through cli.run's pipeline)

Every ``import``/``from`` statement counts, including those inside functions (a lazy import
is still an arrow).
"""

from __future__ import annotations

import ast
import functools
from collections import defaultdict
from pathlib import Path

import flexshaft

ROOT = Path(flexshaft.__file__).parent

LAYERS = {
    "units": 0,
    "resolution": 0,
    "parallel": 0,
    "netcdf": 0,
    "files": 0,
    "plot": 0,
    "design": 1,
    "laminate": 2,
    "strength": 2,
    "buckling": 2,
    "elements": 2,
    "assembly": 3,
    "analyses": 4,
    "thermal": 5,
    "sweep": 6,
    "verdict": 7,
    "optimize": 8,
    "thesis": 8,
    "comparison": 8,
    "montecarlo": 8,
    "validation": 8,
    "report": 9,
    "cli": 10,
    "explore": 10,
    "__main__": 10,  # ``python -m flexshaft``: the cli's app
}


def module_name(path: Path) -> str:
    parts = path.relative_to(ROOT.parent).with_suffix("").parts
    return ".".join(parts[:-1] if parts[-1] == "__init__" else parts)


@functools.cache
def imports() -> dict[str, set[tuple[str, tuple[str, ...]]]]:
    """module -> {(imported module, names imported from it)}: the package parsed once per test
    module (the three checks below read the same graph; none changes it)."""
    out: dict[str, set] = defaultdict(set)
    for path in ROOT.rglob("*.py"):
        name = module_name(path)
        package = name if path.name == "__init__.py" else name.rpartition(".")[0]
        for node in ast.walk(ast.parse(path.read_text())):
            if isinstance(node, ast.ImportFrom):
                module = node.module or ""
                if node.level:
                    base = package.split(".")
                    base = base[: len(base) - node.level + 1]
                    module = ".".join(base + ([module] if module else []))
                if module.startswith("flexshaft"):
                    out[name].add((module, tuple(a.name for a in node.names)))
            elif isinstance(node, ast.Import):
                for alias in node.names:
                    if alias.name.startswith("flexshaft"):
                        out[name].add((alias.name, ()))
    return out


def layer(module: str) -> int | None:
    parts = module.split(".")
    return LAYERS.get(parts[1]) if len(parts) > 1 else None


def test_every_subpackage_has_a_layer():
    top = {
        p.stem if p.is_file() else p.name
        for p in ROOT.iterdir()
        if (p.suffix == ".py" or (p.is_dir() and (p / "__init__.py").exists())) and p.name != "__init__.py"
    }
    assert top - set(LAYERS) == set(), "a new top-level module needs a layer in this test and in the docs"


def test_no_import_runs_up_the_layers():
    upward = []
    for source, targets in imports().items():
        here = layer(source)
        for target, _ in targets:
            there = layer(target)
            if here is not None and there is not None and there > here:
                upward.append(f"{source} -> {target}")
    assert not upward, "\n".join(upward)


def test_import_graph_has_no_cycle():
    graph = {source: {t for t, _ in targets} for source, targets in imports().items()}
    modules = set(graph) | {t for ts in graph.values() for t in ts}

    def resolve(target: str) -> str:
        # "from flexshaft.analyses import x" depends on the package's __init__
        return target if target in modules else target.rpartition(".")[0]

    state: dict[str, int] = {}
    cycles = []

    def visit(node: str, stack: list[str]) -> None:
        state[node] = 1
        for nxt in sorted(resolve(t) for t in graph.get(node, ())):
            if nxt == node or nxt.startswith(node + "."):  # a package importing its own submodules
                continue
            if state.get(nxt) == 1:
                cycles.append(" -> ".join(stack[stack.index(nxt) :] + [nxt]) if nxt in stack else f"{node} -> {nxt}")
            elif state.get(nxt) is None:
                visit(nxt, stack + [nxt])
        state[node] = 2

    for module in sorted(modules):
        if state.get(module) is None:
            visit(module, [module])
    assert not cycles, "\n".join(cycles)


def test_no_private_name_crosses_a_module():
    crossing = []
    for source, targets in imports().items():
        for target, names in targets:
            for name in names:
                if name.startswith("_") and not name.startswith("__"):
                    crossing.append(f"{source} imports {target}.{name}")
    assert not crossing, "\n".join(crossing)
