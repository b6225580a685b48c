"""A real JupyterLab for the browser tests: started on a free localhost port, stopped after.

The server runs from a given Python environment (this one by default; the browser tests'
shared ``lab`` fixture uses a fresh venv with the built wheel, see conftest.py), so the
kernel imports that environment's ``trinormal``. No token, no news feed, no update check;
its root folder is a temporary one that holds only the notebooks a test writes there. The
same server also serves Jupyter Notebook 7 (``Lab.notebook7_url``).
"""

from __future__ import annotations

import json
import os
import re
import signal
import socket
import subprocess
import sys
import time
import urllib.error
import urllib.request
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from pathlib import Path
from typing import Any

#: How long JupyterLab may take to answer its status API after it starts.
START_TIMEOUT_S = 90


@dataclass
class Lab:
    """A running JupyterLab: its base URL and its root folder.

    ``kept`` names the notebooks (paths in the root) whose kernels outlive a test: a
    module fixture that opened one for several tests adds it, and removes it when done.
    """

    url: str
    root: Path
    kept: set[str] = field(default_factory=set)

    def write_notebook(self, name: str, cells: list[str]) -> str:
        """Write a notebook of code cells into the root; return its URL in JupyterLab."""
        nb = {
            "cells": [
                {
                    "cell_type": "code",
                    "execution_count": None,
                    "metadata": {},
                    "outputs": [],
                    "source": source,
                }
                for source in cells
            ],
            "metadata": {
                "kernelspec": {"display_name": "Python 3", "language": "python", "name": "python3"}
            },
            "nbformat": 4,
            "nbformat_minor": 5,
        }
        (self.root / name).write_text(json.dumps(nb), encoding="utf-8")
        # ?reset: a fresh workspace, not the tabs an earlier test left open on this server
        return f"{self.url}lab/tree/{name}?reset"

    def notebook7_url(self, name: str) -> str:
        """The URL of a notebook in the root, opened in Jupyter Notebook 7 instead of JupyterLab."""
        return f"{self.url}notebooks/{name}"

    def shutdown_kernels(self) -> None:
        """Close every session but the kept ones, and stop its kernel (between tests)."""
        with urllib.request.urlopen(self.url + "api/sessions", timeout=10) as r:
            sessions = json.load(r)
        for session in sessions:
            if session["path"] in self.kept:
                continue
            request = urllib.request.Request(
                f"{self.url}api/sessions/{session['id']}", method="DELETE"
            )
            try:
                with urllib.request.urlopen(request, timeout=30):
                    pass
            except urllib.error.HTTPError:  # already gone (its kernel died or was closed)
                pass


def free_port() -> int:
    with socket.socket() as s:
        s.bind(("127.0.0.1", 0))
        return int(s.getsockname()[1])


@contextmanager
def running_lab(root: Path, python: str | Path = sys.executable) -> Iterator[Lab]:
    """Start JupyterLab on 127.0.0.1 and a free port; stop it (and its kernels) afterwards.

    ``python`` is the interpreter of the environment it runs from (the kernel's too).
    """
    port = free_port()
    args = [
        str(python), "-m", "jupyter", "lab", "--no-browser", f"--port={port}",
        "--ServerApp.ip=127.0.0.1", "--ServerApp.token=", "--ServerApp.password=",
        "--ServerApp.disable_check_xsrf=True", f"--ServerApp.root_dir={root}",
        "--LabApp.news_url=None",
        "--LabApp.check_for_updates_class=jupyterlab.NeverCheckForUpdate",
    ]  # fmt: skip
    if hasattr(os, "geteuid") and os.geteuid() == 0:
        args.append("--allow-root")
    # no "get notified about Jupyter news?" prompt over the notebook
    settings = root.parent / "lab-settings" / "@jupyterlab" / "apputils-extension"
    settings.mkdir(parents=True, exist_ok=True)
    (settings / "notification.jupyterlab-settings").write_text('{"fetchNews": "false"}')
    # every cell in the page (no windowing), so a test can reach any cell of a long notebook
    tracker = root.parent / "lab-settings" / "@jupyterlab" / "notebook-extension"
    tracker.mkdir(parents=True, exist_ok=True)
    (tracker / "tracker.jupyterlab-settings").write_text('{"windowingMode": "none"}')
    args.append(f"--LabApp.user_settings_dir={root.parent / 'lab-settings'}")
    args.append(f"--JupyterNotebookApp.user_settings_dir={root.parent / 'lab-settings'}")
    args.append(f"--LabApp.workspaces_dir={root.parent / 'lab-workspaces'}")
    log = (root.parent / f"jupyterlab-{port}.log").open("w")
    env = {**os.environ, "JUPYTER_CONFIG_DIR": str(root.parent / "config")}
    # the environment's own scripts first, as if it were activated
    env["PATH"] = os.pathsep.join([str(Path(python).parent), env.get("PATH", "")])
    env.pop("VIRTUAL_ENV", None)
    proc = subprocess.Popen(args, stdout=log, stderr=subprocess.STDOUT, env=env,
                            start_new_session=True)  # fmt: skip
    url = f"http://127.0.0.1:{port}/"
    try:
        deadline = time.monotonic() + START_TIMEOUT_S
        while True:
            try:
                with urllib.request.urlopen(url + "api/status", timeout=2) as r:
                    if r.status == 200:
                        break
            except OSError:
                pass
            if proc.poll() is not None or time.monotonic() > deadline:
                log.flush()
                text = (root.parent / f"jupyterlab-{port}.log").read_text()[-3000:]
                raise RuntimeError(f"JupyterLab did not start:\n{text}")
            time.sleep(0.3)
        yield Lab(url=url, root=root)
    finally:
        os.killpg(proc.pid, signal.SIGTERM)
        try:
            proc.wait(timeout=15)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
        log.close()


def run_all(page: Any) -> None:
    """Run every cell with JupyterLab's own Run menu, as a student would."""
    page.locator(".lm-MenuBar-itemLabel", has_text="Run").first.click()
    page.locator(".lm-Menu-itemLabel", has_text="Run All Cells").first.click()


def kernel_ready(lab: Lab, name: str | None = None, timeout_s: float = 60) -> None:
    """Wait until notebook ``name`` (else any) has a kernel that is idle and connected to a page."""
    deadline = time.monotonic() + timeout_s
    while time.monotonic() < deadline:
        try:
            with urllib.request.urlopen(lab.url + "api/sessions", timeout=5) as r:
                sessions = json.load(r)
        except OSError:  # a kernel of an earlier test is shutting down, or the machine is busy
            time.sleep(0.3)
            continue
        kernels = [s["kernel"] for s in sessions if name in (None, s["path"]) and s.get("kernel")]
        if any(k["execution_state"] == "idle" and k["connections"] > 0 for k in kernels):
            return
        time.sleep(0.3)
    raise TimeoutError(
        f"no idle, connected kernel for {name or 'any notebook'} after {timeout_s} s"
    )


#: A coordinate the view wrote (a drag, an arrow key, a slider): a text on the 0.1 grid.
GRID = re.compile(r"-?\d+(\.\d)?")


def open_notebook(lab: Lab, page: Any, name: str, app: str = "lab") -> None:
    """Open notebook ``name`` of the root in JupyterLab (``app="lab"``) or Notebook 7
    (``"notebook"``) on a fresh kernel, and wait until that kernel is ready."""
    lab.shutdown_kernels()  # a fresh kernel for this page
    url = f"{lab.url}lab/tree/{name}?reset" if app == "lab" else lab.notebook7_url(name)
    page.goto(url)
    page.wait_for_selector(".jp-Notebook .jp-Cell", timeout=60_000)
    kernel_ready(lab, name)


def restart_and_clear(page: Any) -> None:
    """A fresh kernel for the open notebook, and no outputs: the Kernel menu's own command.

    The page keeps the loaded app; JupyterLab (and Notebook 7) clears the outputs only once
    the new kernel has answered, so after this the notebook runs on that fresh kernel.
    """
    page.locator(".lm-MenuBar-itemLabel", has_text="Kernel").first.click()
    page.locator(".lm-Menu-itemLabel", has_text="Restart Kernel and Clear").first.click()
    page.locator(".jp-Dialog .jp-mod-accept").click()
    page.wait_for_selector(".jp-Dialog", state="detached")
    page.wait_for_function(
        "() => !document.querySelector('.jp-Notebook .jp-OutputArea-output')", timeout=60_000
    )
    wait_idle(page)


def execution_counts(page: Any) -> list[str]:
    """The prompts of the notebook's code cells (``[1]:`` once the first has run).

    Read once no cell waits for its reply (``[*]``): the kernel may print a cell's output
    before it answers that the cell is done.
    """
    page.wait_for_function(
        """() => ![...document.querySelectorAll('.jp-Notebook .jp-CodeCell .jp-InputArea-prompt')]
            .some((p) => p.textContent.includes('*'))""",
        timeout=30_000,
    )
    return [
        str(t).strip()
        for t in page.locator(".jp-Notebook .jp-CodeCell .jp-InputArea-prompt").all_inner_texts()
    ]


def wait_idle(page: Any, timeout_ms: int = 60_000) -> None:
    """Wait until the notebook's kernel is idle."""
    page.wait_for_function(
        """() => {
            const s = document.querySelector('.jp-Notebook-ExecutionIndicator');
            return s && s.getAttribute('data-status') === 'idle';
        }""",
        timeout=timeout_ms,
    )


def output_text(page: Any, cell_index: int) -> str:
    """The text output of one code cell (0-based among all cells)."""
    cell = page.locator(".jp-Notebook .jp-Cell").nth(cell_index)
    return str(cell.locator(".jp-OutputArea-output").last.inner_text())


def run_cell(page: Any, cell_index: int) -> None:
    """Select one cell and run it with Shift+Enter."""
    cell = page.locator(".jp-Notebook .jp-Cell").nth(cell_index)
    cell.scroll_into_view_if_needed()
    cell.locator(".jp-InputArea-prompt").click()
    page.keyboard.press("Shift+Enter")
