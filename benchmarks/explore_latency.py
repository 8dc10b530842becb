"""Latency of one explorer update: the server side and the round trip in a browser.

    OPENBLAS_NUM_THREADS=1 .venv/bin/python benchmarks/explore_latency.py [--updates 30] [--design FILE]
        [--no-browser]

Starts ``flexshaft explore`` (as a user does, its own process and its workers; default the
embedded tuned design) and changes K_p of the first active bearing ``--updates`` times, each to
a value not seen before (log-spaced from 2e5 to 2e6 N/m, so that no cache helps):

* **server side**, through the JSON API (``POST /api/update``, one request at a time): the time
  the server takes from the request to its answer (validation, the assessment in a worker at the
  screening grids with the Campbell diagram, the verdict and figures as JSON; ``server_s``), the
  CPU time of the worker's assessment and payload (``cpu_s``), and the HTTP time seen by the
  client;
* **browser round trip**, in headless Chromium (after the time to open the page to its first
  verdict, plotly.js of 4.8 MB included) (Debian's, driven by playwright as the tests
  do): from typing the new K_p into its field (Enter) to the verdict table and every figure
  redrawn (the page's own measure, ``performance.now()`` around the request and the drawing).

Printed: median and p95 (nearest rank) of each, and the machine facts. The first update (the
workers' first assessment) is left out of the statistics and printed apart.
"""

from __future__ import annotations

import argparse
import json
import math
import os
import subprocess
import sys
import time
import urllib.request

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)

import bench_util as bu  # noqa: E402

FLAGS = [
    "--no-sandbox",
    "--disable-gpu",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-quic",
    "--no-first-run",
]


def percentile(values: list[float], q: float) -> float:
    """Nearest-rank percentile (no interpolation: a value that was measured)."""
    ordered = sorted(values)
    return ordered[max(0, math.ceil(q / 100 * len(ordered)) - 1)]


def summary(name: str, values: list[float]) -> str:
    return (
        f"{name:<44} median {sorted(values)[len(values) // 2]:6.3f} s   p95 {percentile(values, 95):6.3f} s   "
        f"(n = {len(values)}, min {min(values):.3f}, max {max(values):.3f})"
    )


def start_server(design: str | None) -> tuple[subprocess.Popen, str]:
    env = {**os.environ, "OPENBLAS_NUM_THREADS": "1", "PYTHONUNBUFFERED": "1"}
    args = [sys.executable, "-c", "import sys; from flexshaft.cli import app; sys.exit(app())", "explore"]
    args += ["--port", "0", "--studies", "none"] + ([design] if design else [])
    server = subprocess.Popen(args, stdout=subprocess.PIPE, text=True, env=env)
    line = server.stdout.readline()
    if "http://" not in line:
        server.kill()
        raise SystemExit(f"the explorer did not start: {line!r}")
    return server, line.split("flexshaft explore: ", 1)[1].split()[0]


def post(url: str, body: dict) -> tuple[dict, float]:
    request = urllib.request.Request(
        url, data=json.dumps(body).encode(), headers={"Content-Type": "application/json"}, method="POST"
    )
    start = time.perf_counter()
    with urllib.request.urlopen(request, timeout=120) as response:
        data = json.loads(response.read())
    return data, time.perf_counter() - start


def gains(n: int, offset: float) -> list[float]:
    """n K_p values [N/m] log-spaced over 2e5..2e6, shifted by ``offset`` (a fraction of a step)."""
    return [float(f"{2e5 * 10 ** ((k + offset) / max(n, 2)):.6g}") for k in range(n)]


def server_side(url: str, n: int) -> None:
    init = json.loads(urllib.request.urlopen(url + "api/init", timeout=60).read())
    key = next(c["key"] for c in init["controls"] if c["key"].endswith(".kp"))
    server, cpu, http = [], [], []
    for seq, kp in enumerate(gains(n + 1, 0.0)):
        data, seconds = post(url + "api/update", {"session": "bench", "seq": seq, "base": "file", "edits": {key: kp}})
        if seq == 0:
            print(
                f"first update (the workers' first assessment): server {data['server_s']:.3f} s, "
                f"CPU {data['results']['cpu_s']:.3f} s"
            )
            continue
        server.append(data["server_s"])
        cpu.append(data["results"]["cpu_s"])
        http.append(seconds)
    print(f"server side, {key} changed {n} times:")
    print("  " + summary("server: request to answer (server_s)", server))
    print("  " + summary("worker CPU: assessment + payload (cpu_s)", cpu))
    print("  " + summary("HTTP round trip (client)", http))


def browser_side(url: str, n: int) -> None:
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path="/usr/bin/chromium", args=FLAGS)
        page = browser.new_page(viewport={"width": 1400, "height": 1000})
        start = time.perf_counter()
        page.goto(url)
        wait_seq(page, -1)
        print(f"page opened to its first verdict and figures in {time.perf_counter() - start:.2f} s")
        key = page.evaluate("flexshaftExplore.state.controls.find(c => c.key.endsWith('.kp')).key")
        selector = f"[id='ctl-{key}']"
        trips = []
        for kp in gains(n, 0.5):  # values between the server-side ones: not seen before
            before = int(page.evaluate("Number(document.body.dataset.seq)"))
            page.fill(selector, f"{kp:g}")
            page.press(selector, "Enter")
            wait_seq(page, before)
            trips.append(float(page.evaluate("Number(document.body.dataset.roundTrip)")))
        browser.close()
    print(f"browser (headless Chromium), {key} typed {n} times:")
    print("  " + summary("round trip: Enter to verdict and figures drawn", trips))


def wait_seq(page, before: int, timeout: float = 120.0) -> None:
    deadline = time.monotonic() + timeout
    while page.evaluate(f"Number(document.body.dataset.seq || -1) <= {before}"):
        if time.monotonic() > deadline:
            raise SystemExit("timed out waiting for an update")
        page.wait_for_timeout(10)


def main() -> None:
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--updates", type=int, default=30)
    parser.add_argument("--design", default=None)
    parser.add_argument("--no-browser", action="store_true")
    args = parser.parse_args()
    print(json.dumps(bu.machine_info()))
    server, url = start_server(args.design)
    try:
        server_side(url, args.updates)
        if not args.no_browser:
            browser_side(url, args.updates)
    finally:
        server.terminate()
        server.wait(timeout=30)


if __name__ == "__main__":
    main()
