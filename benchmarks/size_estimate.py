"""The problem-size time estimate against the measured CPU time (docs/limits.md, section 5).

For each case: :func:`flexshaft.assembly.size.problem_size`'s time estimate, its largest term,
and the CPU time of the work it estimates, measured in the same fresh process (one BLAS
thread), the median of ``--repeats`` runs (the first one cold, after the imports):

* ``assess``: ``flexshaft.assess(design, resolution)`` at SCREENING, VERDICT and REPORT;
* ``model``: ``build_model(design)`` and ``modes(model, operating speed)``;
* ``run``: the whole ``flexshaft run DESIGN --studies report`` command (a child process: CPU
  of it and of its workers, imports included).

The designs are the embedded tuned and baseline designs at their own meshes and at 100, 200
and 400 shaft elements (the boom's elements in the same proportion, 2/3). The estimate must be
an upper bound of the measured CPU, within a factor of about 2.5 (``ratio`` = estimate /
measured); ``--quick`` times only the default meshes.

    OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/size_estimate.py [--quick] [--json FILE]
"""

from __future__ import annotations

import argparse
import json
import os
import resource
import statistics
import subprocess
import sys
import tempfile
from pathlib import Path

HERE = Path(__file__).resolve().parent
sys.path.insert(0, str(HERE))

import bench_util as bu  # noqa: E402

JOB = r"""
import json, sys, time, warnings
import flexshaft as fs
from flexshaft.assembly.size import ProblemSizeWarning, problem_size
from flexshaft.design import embedded_design, with_overrides
from flexshaft.resolution import RESOLUTIONS
name, elements, analysis, resolution = sys.argv[1], int(sys.argv[2]), sys.argv[3], sys.argv[4]
repeats = int(sys.argv[5])
warnings.simplefilter("ignore", ProblemSizeWarning)
design = embedded_design(name)
if elements:
    design = with_overrides(design, {"mesh.shaft_elements": elements, "mesh.boom_elements": round(2 * elements / 3)})
res = RESOLUTIONS[resolution]
size = problem_size(design, analysis, res)
def work():
    if analysis == "model":
        model = fs.build_model(design)
        fs.modes(model, speed=design.operating.speed_rad_s)
    else:
        fs.assess(design, res)
cpu = []
for _ in range(repeats):
    c = time.process_time()
    work()
    cpu.append(time.process_time() - c)
print(json.dumps({"estimate": size.time_seconds, "terms": size.time, "dofs": size.dofs, "cpu": cpu}))
"""

ESTIMATE = r"""
import json, sys, warnings
from flexshaft.assembly.size import ProblemSizeWarning, problem_size
from flexshaft.design import embedded_design, with_overrides
name, elements = sys.argv[1], int(sys.argv[2])
warnings.simplefilter("ignore", ProblemSizeWarning)
design = embedded_design(name)
if elements:
    design = with_overrides(design, {"mesh.shaft_elements": elements, "mesh.boom_elements": round(2 * elements / 3)})
size = problem_size(design, "run")
print(json.dumps({"estimate": size.time_seconds, "terms": size.time, "dofs": size.dofs}))
"""

SRC = str(HERE.parent / "src")


def _job(code: str, *args) -> dict:
    env = dict(bu.single_thread_env(1), PYTHONPATH=SRC)
    out = subprocess.run([sys.executable, "-c", code, *map(str, args)], env=env, capture_output=True, text=True)
    if out.returncode:
        raise SystemExit(f"the job {args} failed:\n{out.stderr}")
    return json.loads(out.stdout.strip().splitlines()[-1])


def _design_file(name: str, elements: int, folder: str) -> str:
    """The embedded design ``name`` as a TOML file, its mesh overridden when ``elements``."""
    from flexshaft.design import embedded_text

    text = embedded_text(name)
    if elements:
        boom = round(2 * elements / 3)
        lines = []
        section = ""
        for line in text.splitlines():
            stripped = line.strip()
            if stripped.startswith("["):
                section = stripped
            if section == "[mesh]" and stripped.startswith("shaft_elements"):
                line = f"shaft_elements = {elements}"
            elif section == "[mesh]" and stripped.startswith("boom_elements"):
                line = f"boom_elements = {boom}"
            lines.append(line)
        text = "\n".join(lines) + "\n"
    path = os.path.join(folder, f"{name}-{elements or 'default'}.toml")
    with open(path, "w") as f:
        f.write(text)
    return path


def run_case(name: str, elements: int, repeats: int) -> dict:
    """``flexshaft run`` on the design: estimate and CPU of the command and its children."""
    size = _job(ESTIMATE, name, elements)
    cpu = []
    with tempfile.TemporaryDirectory() as folder:
        path = _design_file(name, elements, folder)
        env = dict(bu.single_thread_env(1), PYTHONPATH=SRC)
        for i in range(repeats):
            before = resource.getrusage(resource.RUSAGE_CHILDREN)
            out = subprocess.run(
                [
                    str(Path(sys.executable).with_name("flexshaft")),
                    "run",
                    path,
                    "--studies",
                    "report",
                    "--force",
                    "--out",
                    f"{folder}/r{i}",
                ],
                env=env,
                capture_output=True,
                text=True,
            )
            after = resource.getrusage(resource.RUSAGE_CHILDREN)
            if out.returncode:
                raise SystemExit(f"flexshaft run {path} failed ({out.returncode}):\n{out.stderr[-2000:]}")
            cpu.append((after.ru_utime + after.ru_stime) - (before.ru_utime + before.ru_stime))
    return dict(size, cpu=cpu)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--quick", action="store_true", help="only the designs' own meshes")
    parser.add_argument("--repeats", type=int, default=3)
    parser.add_argument("--designs", default="tuned,baseline")
    parser.add_argument("--meshes", default="0,100,200,400", help="shaft elements; 0 = the design's own")
    parser.add_argument("--analyses", default="screening,verdict,report,model,run")
    parser.add_argument("--json", help="write the results to this file")
    args = parser.parse_args()
    meshes = [0] if args.quick else [int(m) for m in args.meshes.split(",")]
    print(json.dumps(bu.machine_info()))
    print(f"{'design':9} {'mesh':>7} {'DOFs':>6} {'analysis':16} {'estimate':>9} {'CPU':>8} {'ratio':>6}  largest term")
    rows = []
    for name in args.designs.split(","):
        for elements in meshes:
            for what in args.analyses.split(","):
                if what == "run":
                    if elements > 200:
                        continue  # the whole run at 400 elements takes many minutes
                    result = run_case(name, elements, args.repeats)
                elif what == "model":
                    result = _job(JOB, name, elements, "model", "report", args.repeats)
                else:
                    result = _job(JOB, name, elements, "assess", what, args.repeats)
                cpu = statistics.median(result["cpu"])
                ratio = result["estimate"] / cpu
                terms = result["terms"]
                largest = max(terms, key=terms.get)
                row = dict(result, design=name, elements=elements or "default", analysis=what, median=cpu, ratio=ratio)
                rows.append(row)
                print(
                    f"{name:9} {str(elements or 'default'):>7} {result['dofs']:6d} {what:16} "
                    f"{result['estimate']:9.2f} {cpu:8.2f} {ratio:6.2f}  {largest} ({terms[largest]:.2f} s)",
                    flush=True,
                )
    if args.json:
        Path(args.json).write_text(json.dumps(rows, indent=1))


if __name__ == "__main__":
    bu.reexec_with_threads(1, __file__)
    main()
