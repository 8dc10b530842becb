"""Headless-Chromium checks shared by the report tests (Debian's chromium, no network)."""

from __future__ import annotations

import html
import os
import re
import shutil
import subprocess
from pathlib import Path

import pytest

CHROMIUM_FLAGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-dev-shm-usage",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
]


def chromium_or_skip() -> str:
    """Path of chromium; fail under CI (it must always run there), skip elsewhere."""
    path = (
        "/usr/bin/chromium"
        if Path("/usr/bin/chromium").is_file()
        else (shutil.which("chromium") or shutil.which("chromium-browser"))
    )
    if path is None:
        message = "chromium not installed: run scripts/install_chromium.sh"
        if os.environ.get("CI"):
            pytest.fail(message)
        pytest.skip(message)
    return path


def run_chromium(chromium: str, workdir: Path, *args: str) -> subprocess.CompletedProcess:
    profile = workdir / f"chromium-profile-{len(list(workdir.iterdir()))}"
    return subprocess.run(
        [chromium, *CHROMIUM_FLAGS, f"--user-data-dir={profile}", *args], capture_output=True, text=True, timeout=90
    )


def image_load_title(chromium: str, page: Path, workdir: Path) -> str:
    """Load a test-only copy of ``page`` that sets its title to ``IMAGES-OK:n`` when every
    <img> decoded (``IMAGES-BAD:n`` otherwise); return that title."""
    text = page.read_text(encoding="utf-8")
    probe = (
        "<script>window.addEventListener('load', () => { const images = [...document.images];"
        " document.title = images.length && images.every(i => i.complete && i.naturalWidth > 0)"
        " ? 'IMAGES-OK:' + images.length : 'IMAGES-BAD:' + images.length; });</script>"
    )
    probed = text.replace("default-src 'none';", "default-src 'none'; script-src 'unsafe-inline';", 1)
    probed = probed.replace("</body>", probe + "</body>", 1)
    probe_path = page.parent / (page.stem + "_probe.html")
    probe_path.write_text(probed, encoding="utf-8")
    dump = run_chromium(chromium, workdir, "--virtual-time-budget=5000", "--dump-dom", probe_path.as_uri())
    assert dump.returncode == 0, dump.stderr[-2000:]
    title = re.search(r"<title>(.*?)</title>", dump.stdout, re.DOTALL)
    assert title is not None, dump.stdout[:2000]
    return html.unescape(title.group(1))
