"""Browser tests: Debian's Chromium driven by Playwright, against the built site served here.

The site is the output of ``mkdocs build --strict`` (``make docs-build``) in ``site/``;
set ``TRINORMAL_SITE_DIR`` to test another build. If no build exists, one is made in
a temporary directory. The server listens on 127.0.0.1 on a free port; every request
the browser makes is recorded, and any request to another origin is aborted and
reported by the tests.

Without Chromium the tests skip with a reason, except when ``CI`` is set: then they
fail, because CI installs Chromium (``.ci/run``) and must never skip them.
"""

from __future__ import annotations

import os
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

    page.route("**/*", route)
    page.on("request", lambda req: t.requests.append(req.url))
    page.on("requestfailed", failed)
    page.on("response", response)
    page.on("console", console)
    page.on("pageerror", lambda exc: t.page_errors.append(str(exc)))
    return t
