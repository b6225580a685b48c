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

import functools
import os
import re
import shutil
import subprocess
import sys
import threading
from collections.abc import Iterator
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

import pytest
from browser_support import ROOT, Traffic, is_local

CHROMIUM = os.environ.get("TRINORMAL_CHROMIUM", "/usr/bin/chromium")
CHROMIUM_ARGS = [
    "--headless",
    "--no-sandbox",
    "--disable-gpu",
    "--disable-quic",
    "--no-first-run",
    "--disable-background-networking",
    "--disable-component-update",
    "--disable-sync",
    "--disable-dev-shm-usage",
]


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


def _newest_source() -> float:
    """Modification time of the newest file the site is built from."""
    sources = [ROOT / "mkdocs.yml"]
    for folder, pattern in (("docs", "**/*"), ("notebooks", "*.ipynb"), ("trinormal", "**/*.py")):
        sources += (p for p in (ROOT / folder).glob(pattern) if p.is_file())
    return max(p.stat().st_mtime for p in sources)


@pytest.fixture(scope="session")
def site_dir(tmp_path_factory: pytest.TempPathFactory) -> Path:
    """The built site: TRINORMAL_SITE_DIR, else an up-to-date site/, else a fresh strict build."""
    env = os.environ.get("TRINORMAL_SITE_DIR")
    if env:
        path = Path(env)
        assert (path / "index.html").is_file(), f"TRINORMAL_SITE_DIR={env} holds no built site"
        return path
    built = ROOT / "site"
    if (built / "index.html").is_file() and _newest_source() < (
        built / "index.html"
    ).stat().st_mtime:
        return built  # `make test` has just built it
    out = tmp_path_factory.mktemp("site")
    subprocess.run(
        [sys.executable, "-m", "mkdocs", "build", "--strict", "--quiet", "-d", str(out)],
        cwd=ROOT,
        check=True,
        env={**os.environ, "NO_MKDOCS_2_WARNING": "1"},
    )
    return out


class _QuietHandler(SimpleHTTPRequestHandler):
    def log_message(self, format: str, *args: Any) -> None:
        pass


def _site_path(site_dir: Path) -> str:
    """The path the site is built for (``/trinormal/`` for site_url .../trinormal/), from its sitemap."""
    sitemap = site_dir / "sitemap.xml"
    text = sitemap.read_text(encoding="utf-8") if sitemap.is_file() else ""
    m = re.search(r"<loc>\s*[a-z]+://[^/<]+(/[^<]*?)\s*</loc>", text)
    path = m.group(1) if m else "/"
    return path if path.endswith("/") else path + "/"


class _PrefixHandler(_QuietHandler):
    """Serve the site under its own path, as a static host would (its 404 page needs that)."""

    prefix = "/"

    def translate_path(self, path: str) -> str:
        if not path.startswith(self.prefix):
            return str(Path(self.directory) / "does-not-exist")
        return super().translate_path("/" + path[len(self.prefix) :])


@pytest.fixture(scope="session")
def server(site_dir: Path) -> Iterator[str]:
    """Serve the built site on 127.0.0.1 (a free port) under its path; yield its base URL."""
    prefix = _site_path(site_dir)
    handler_class = type("Handler", (_PrefixHandler,), {"prefix": prefix})
    handler = functools.partial(handler_class, directory=str(site_dir))
    httpd = ThreadingHTTPServer(("127.0.0.1", 0), handler)
    thread = threading.Thread(target=httpd.serve_forever, daemon=True)
    thread.start()
    try:
        yield f"http://127.0.0.1:{httpd.server_address[1]}{prefix}"
    finally:
        httpd.shutdown()
        httpd.server_close()


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
