"""Helpers shared by the browser tests (kept out of conftest.py so tests can import them)."""

from __future__ import annotations

import functools
import os
import re
import subprocess
import sys
import tempfile
import threading
from collections.abc import Iterator
from contextlib import contextmanager
from dataclasses import dataclass, field
from http.server import SimpleHTTPRequestHandler, ThreadingHTTPServer
from pathlib import Path
from typing import Any

ROOT = Path(__file__).resolve().parents[2]

#: Debian's Chromium (Playwright cannot download browsers here) and flags that keep it offline.
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


@dataclass
class Traffic:
    """What one page did on the network and in its console."""

    origin: str
    requests: list[str] = field(default_factory=list)
    off_origin: list[str] = field(default_factory=list)
    failed: list[str] = field(default_factory=list)
    bad_status: list[str] = field(default_factory=list)
    console_errors: list[str] = field(default_factory=list)
    page_errors: list[str] = field(default_factory=list)

    served: set[str] = field(default_factory=set)

    def problems(self) -> list[str]:
        # A navigation cancels the requests still in flight (net::ERR_ABORTED): that is not a
        # failure when the same URL was served successfully at another time.
        failed = [
            f
            for f in self.failed
            if not (f.endswith(" net::ERR_ABORTED") and f.rsplit(" ", 1)[0] in self.served)
        ]
        return (
            [f"request to another origin: {u}" for u in self.off_origin]
            + [f"failed request: {u}" for u in failed]
            + [f"HTTP error: {u}" for u in self.bad_status]
            + [f"console error: {m}" for m in self.console_errors]
            + [f"page error: {m}" for m in self.page_errors]
        )


def is_local(url: str, origin: str) -> bool:
    return url.startswith(origin) or url.startswith(("data:", "blob:", "about:"))


def site_pages(site_dir: Path) -> list[str]:
    """Every HTML page of the build, as a path relative to the site root (``guide/``)."""
    pages = []
    for html in sorted(site_dir.rglob("index.html")):
        rel = html.parent.relative_to(site_dir).as_posix()
        pages.append("" if rel == "." else rel + "/")
    return pages


def source_pages() -> list[str]:
    """Every page the site is built from, as ``site_pages`` names them, read from the sources.

    ``docs/**/*.md`` (``x/index.md`` is ``x/``, ``x.md`` is ``x/`` too) and one page per
    ``notebooks/*.ipynb``. Known before any build, so tests can be parametrized by page;
    ``test_every_page.py`` checks that the build has exactly these pages.
    """
    pages = []
    for md in (ROOT / "docs").rglob("*.md"):
        rel = md.relative_to(ROOT / "docs")
        if rel.parts[0] in ("hooks", "notebooks"):
            continue
        folder = rel.parent if rel.stem == "index" else rel.with_suffix("")
        pages.append("" if folder.as_posix() == "." else folder.as_posix() + "/")
    pages += [f"notebooks/{nb.stem}/" for nb in (ROOT / "notebooks").glob("*.ipynb")]
    return sorted(pages)


def newest_source() -> float:
    """Modification time of the newest file the site is built from."""
    sources = [ROOT / "mkdocs.yml"]
    for folder, pattern in (("docs", "**/*"), ("notebooks", "*.ipynb"), ("trinormal", "**/*")):
        sources += (p for p in (ROOT / folder).glob(pattern) if p.is_file())
    return max(p.stat().st_mtime for p in sources)


def built_site(out: Path | None = None) -> Path:
    """The built site: TRINORMAL_SITE_DIR, else an up-to-date site/, else a fresh strict build.

    The fresh build goes to ``out`` (a temporary folder when not given).
    """
    env = os.environ.get("TRINORMAL_SITE_DIR")
    if env:
        path = Path(env)
        if not (path / "index.html").is_file():
            raise FileNotFoundError(f"TRINORMAL_SITE_DIR={env} holds no built site")
        return path
    index = ROOT / "site" / "index.html"
    if index.is_file() and newest_source() < index.stat().st_mtime:
        return ROOT / "site"  # `make test` has just built it
    out = out or Path(tempfile.mkdtemp(prefix="trinormal-site-"))
    subprocess.run(
        [sys.executable, "-m", "mkdocs", "build", "--strict", "--quiet", "-d", str(out)],
        cwd=ROOT,
        check=True,
        env={**os.environ, "NO_MKDOCS_2_WARNING": "1"},
    )
    return out


def site_path(site_dir: Path) -> str:
    """The path the site is built for (``/trinormal/`` for site_url .../trinormal/), from its sitemap."""
    sitemap = site_dir / "sitemap.xml"
    text = sitemap.read_text(encoding="utf-8") if sitemap.is_file() else ""
    m = re.search(r"<loc>\s*[a-z]+://[^/<]+(/[^<]*?)\s*</loc>", text)
    path = m.group(1) if m else "/"
    return path if path.endswith("/") else path + "/"


class QuietHandler(SimpleHTTPRequestHandler):
    """A static file handler that logs nothing."""

    def log_message(self, format: str, *args: Any) -> None:
        pass


class _PrefixHandler(QuietHandler):
    """Serve the site under its own path, as a static host would (its 404 page needs that)."""

    prefix = "/"

    def translate_path(self, path: str) -> str:
        if not path.startswith(self.prefix):
            return str(Path(self.directory) / "does-not-exist")
        return super().translate_path("/" + path[len(self.prefix) :])


@contextmanager
def serve_site(site_dir: Path) -> Iterator[str]:
    """Serve a built site on 127.0.0.1 (a free port) under its path; yield its base URL."""
    prefix = site_path(site_dir)
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
