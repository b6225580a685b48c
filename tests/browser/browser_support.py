"""Helpers shared by the browser tests (kept out of conftest.py so tests can import them)."""

from __future__ import annotations

from dataclasses import dataclass, field
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]


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
