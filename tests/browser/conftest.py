"""Browser tests: Debian's Chromium driven by Playwright, against the built site served here.

The site is the output of ``mkdocs build --strict`` (``make docs-build``) in ``site/``;
set ``TRINORMAL_SITE_DIR`` to test another build. If no build exists, one is made in
a temporary directory. The server listens on 127.0.0.1 on a free port; every request
the browser makes is recorded, and any request to another origin is aborted and
reported by the tests.

Without Chromium the tests skip with a reason, except when ``CI`` is set: then they
fail, because CI installs Chromium (``.ci/run``) and must never skip them.

Shared by the whole run (session fixtures):

* ``wheel`` — the wheel built from this tree, once per run (pytest-xdist workers share it);
* ``wheel_env`` — a fresh venv outside the repository with ``wheel[notebooks]`` installed
  at uv.lock's versions, once per run, as a teacher or a JupyterHub installs it;
* ``lab`` — one JupyterLab server started from ``wheel_env`` (it also serves Notebook 7),
  for every test that drives JupyterLab. Those tests live in files named
  ``test_*lab*.py``, which ``--dist loadgroup`` sends to one xdist worker, so there is
  one server; each test's kernels are stopped after it.
"""

from __future__ import annotations

import os
import re
import shutil
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest
from browser_support import (
    CHROMIUM,
    CHROMIUM_ARGS,
    Traffic,
    built_site,
    is_local,
    serve_site,
)
from install_support import build_wheel, install, shared
from jupyterlab_support import Lab, running_lab

#: Test files that use the run's JupyterLab server (the ``lab`` fixture): their names contain
#: "lab" (test_jupyterlab.py, test_wheel_lab.py); with ``--dist loadgroup`` they all run on one
#: xdist worker, so the run starts one server.
LAB_FILES = re.compile(r"^tests/browser/test_[^/]*lab[^/]*\.py::")


def pytest_collection_modifyitems(items: list[pytest.Item]) -> None:
    """Refuse a test that uses ``lab`` from a file the scheduler would not keep together."""
    for item in items:
        if "lab" in getattr(item, "fixturenames", ()) and not LAB_FILES.match(item.nodeid):
            raise pytest.UsageError(
                f"{item.nodeid} uses the shared JupyterLab server: move it to a file named "
                "tests/browser/test_*lab*.py, which --dist loadgroup keeps on one worker"
            )


def pytest_xdist_make_scheduler(config: pytest.Config, log: Any) -> Any:
    """``--dist loadgroup``: the JupyterLab files together on one worker, every other test alone.

    (pytest-xdist 3.8's own loadgroup reads ``xdist_group`` marks by renaming node ids, which
    pytest 9.2 no longer allows; this scheduler groups by file name instead.)
    """
    if config.getvalue("dist") != "loadgroup":
        return None
    from xdist.scheduler import LoadScopeScheduling

    class LabTogether(LoadScopeScheduling):  # type: ignore[misc]
        def _split_scope(self, nodeid: str) -> str:
            return "jupyterlab" if LAB_FILES.match(nodeid) else nodeid

    return LabTogether(config, log)


def _chromium_or_skip() -> str:
    path = CHROMIUM if os.path.exists(CHROMIUM) else shutil.which("chromium")
    if path:
        return path
    reason = (
        f"Chromium not found at {CHROMIUM}: install it with `apt-get install -y chromium` "
        "(the browser tests use Debian's Chromium; Playwright cannot download browsers here)"
    )
    if os.environ.get("CI"):
        pytest.fail(reason + " — CI is set, so the browser tests must run", pytrace=False)
    pytest.skip(reason)


@pytest.fixture(scope="session")
def browser_type_launch_args(browser_type_launch_args: dict[str, Any]) -> dict[str, Any]:
    """Launch Debian's Chromium with flags that keep it off the network."""
    return {
        **browser_type_launch_args,
        "executable_path": _chromium_or_skip(),
        "args": CHROMIUM_ARGS,
        "headless": True,
    }


@pytest.fixture(scope="session")
def site_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The built site: TRINORMAL_SITE_DIR, else an up-to-date site/, else a fresh strict build."""
    return built_site(tmp_path_factory.mktemp("site"))


@pytest.fixture(scope="session")
def server(site_dir: Path) -> Iterator[str]:
    """Serve the built site on 127.0.0.1 (a free port) under its path; yield its base URL."""
    with serve_site(site_dir) as url:
        yield url


@pytest.fixture
def traffic(page: Any, server: str) -> Traffic:
    """Record the page's requests and errors; abort anything that leaves 127.0.0.1."""
    t = Traffic(origin=server.rstrip("/"))

    def route(r: Any) -> None:
        url = r.request.url
        if is_local(url, t.origin):
            r.continue_()
        else:
            t.off_origin.append(url)
            r.abort()

    def failed(req: Any) -> None:
        if req.url not in t.off_origin:
            t.failed.append(f"{req.url} {req.failure}")

    def response(resp: Any) -> None:
        if resp.status >= 400:
            t.bad_status.append(f"{resp.status} {resp.url}")
        else:
            t.served.add(resp.url)

    def console(msg: Any) -> None:
        if msg.type == "error":
            t.console_errors.append(msg.text)

    # Only requests that leave the site are routed: a pattern (not a function) is matched by the
    # browser's side, so the site's own requests are not each sent through Python and back.
    page.route(re.compile(rf"^(?!{re.escape(t.origin)}|data:|blob:|about:)"), route)
    page.on("request", lambda req: t.requests.append(req.url))
    page.on("requestfailed", failed)
    page.on("response", response)
    page.on("console", console)
    page.on("pageerror", lambda exc: t.page_errors.append(str(exc)))
    return t


def _run_folder(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """A folder shared by this run's xdist workers (and by no other run)."""
    base = tmp_path_factory.getbasetemp()
    return base.parent if os.environ.get("PYTEST_XDIST_WORKER") else base


@pytest.fixture(scope="session")
def wheel(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The wheel built from this tree (``uv build``), once per run."""
    return shared(_run_folder(tmp_path_factory), "wheel", build_wheel)


@pytest.fixture(scope="session")
def wheel_env(tmp_path_factory: pytest.TempPathFactory, wheel: Path) -> Path:
    """A fresh venv outside the repository with ``wheel[notebooks]``; its Python."""
    return shared(
        _run_folder(tmp_path_factory), "wheel-env", lambda venv: install(venv, wheel, "notebooks")
    )


@pytest.fixture(scope="session")
def lab(tmp_path_factory: pytest.TempPathFactory, wheel_env: Path) -> Iterator[Lab]:
    """One JupyterLab (and Notebook 7) server for the run, from the wheel's venv."""
    root = tmp_path_factory.mktemp("lab") / "notebooks"
    root.mkdir()
    with running_lab(root, python=wheel_env) as server:
        yield server


@pytest.fixture(autouse=True)
def _stop_lab_kernels(request: pytest.FixtureRequest) -> Iterator[None]:
    """After a test that used the shared server, stop the kernels it started."""
    yield
    if "lab" in request.fixturenames:
        request.getfixturevalue("lab").shutdown_kernels()
