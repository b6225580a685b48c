"""Weight of every page of the built site, cold, as a reader's browser loads it.

Each page is opened in a fresh browser context (empty cache) at 1280x800 and every request it
makes until the network is idle is recorded: the HTML, stylesheets, scripts, fonts, images. Each
file is counted the way a static host such as GitHub Pages serves it: text (HTML, CSS, JS, JSON,
SVG) gzip-compressed, files that are compressed already (PNG, WOFF2, ...) as they are.

Printed per page: requests, bytes on the wire, the math engine loaded (if any). Then the goals
(home page at most 300 KB, calculator at most 400 KB) and, measured in the same run, the weight
each page had in the old design, where every page loaded the 2.3 MB MathJax bundle (taken from
git history) instead of KaTeX on the pages with math only. Nothing is asserted.

Run: ``python benchmarks/bench_pages.py`` (uses ``TRINORMAL_SITE_DIR``, else ``site/`` when it
is newer than its sources, else builds the site into a temporary folder). Needs Chromium at
/usr/bin/chromium (or ``TRINORMAL_CHROMIUM``).
"""

from __future__ import annotations

import gzip
import subprocess
import sys
from pathlib import Path
from typing import Any
from urllib.parse import unquote, urlsplit

from playwright.sync_api import sync_playwright

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "browser"))

from browser_support import (  # noqa: E402
    CHROMIUM,
    CHROMIUM_ARGS,
    built_site,
    serve_site,
    site_pages,
)

GOALS = {"": 300_000, "calculator/": 400_000}
COMPRESSED = {".png", ".jpg", ".jpeg", ".gif", ".webp", ".woff2", ".woff", ".zip", ".gz"}
MATHJAX = "docs/assets/vendor/mathjax/tex-svg-full.js"
MATHJAX_CONFIG = "docs/assets/javascripts/mathjax-config.js"


def wire_bytes(data: bytes, suffix: str) -> int:
    """Bytes a static host sends for a file: gzip level 6 for text, as-is for compressed formats."""
    if suffix.lower() in COMPRESSED:
        return len(data)
    return len(gzip.compress(data, compresslevel=6, mtime=0))


def git_blob(path: str) -> bytes | None:
    """A file as it was last committed (HEAD, else the commit before the one that removed it)."""

    def show(rev: str) -> bytes | None:
        r = subprocess.run(["git", "show", f"{rev}:{path}"], cwd=ROOT, capture_output=True)
        return r.stdout if r.returncode == 0 and r.stdout else None

    try:
        if blob := show("HEAD"):
            return blob
        removed = subprocess.run(
            ["git", "rev-list", "-n", "1", "HEAD", "--", path],
            cwd=ROOT,
            capture_output=True,
            text=True,
        ).stdout.strip()
        return show(removed + "^") if removed else None
    except OSError:
        return None


def measure(site: Path) -> list[dict[str, Any]]:
    rows = []
    with serve_site(site) as base, sync_playwright() as pw:
        prefix = urlsplit(base).path
        browser = pw.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS)
        for path in site_pages(site):
            context = browser.new_context(viewport={"width": 1280, "height": 800})
            page = context.new_page()
            urls: list[str] = []
            page.on("requestfinished", lambda req, urls=urls: urls.append(req.url))
            page.goto(base + path)
            page.wait_for_load_state("networkidle")
            files = []
            for url in dict.fromkeys(urls):
                if not url.startswith(base):
                    continue
                rel = unquote(urlsplit(url).path)[len(prefix) :]
                file = site / rel
                if file.is_dir() or rel.endswith("/") or rel == "":
                    file = file / "index.html"
                if file.is_file():
                    data = file.read_bytes()
                    files.append((rel or "index.html", len(data), wire_bytes(data, file.suffix)))
            math = sorted({e for e in ("katex", "mathjax") if any(e in f[0] for f in files)})
            rows.append(
                {
                    "page": path,
                    "requests": len(files),
                    "raw": sum(f[1] for f in files),
                    "wire": sum(f[2] for f in files),
                    "math": math,
                    "math_wire": sum(
                        f[2] for f in files if "katex" in f[0] or f[0].endswith("/math.js")
                    ),
                }
            )
            context.close()
        browser.close()
    return rows


def kb(n: float) -> str:
    return f"{n / 1000:8.1f} KB"


def main() -> None:
    site = built_site()
    rows = measure(site)
    mathjax = git_blob(MATHJAX)
    config = git_blob(MATHJAX_CONFIG) or b""
    old_math = wire_bytes(mathjax, ".js") + wire_bytes(config, ".js") if mathjax else None

    print(f"Site: {site}  (cold, 1280x800, gzip -6 for text as a static host sends it)")
    head = f"{'page':40} {'req':>4} {'raw':>11} {'on the wire':>11}  math    "
    if old_math:
        head += f"{'old design':>11} {'new/old':>8}"
    print(head)
    for r in rows:
        line = f"{r['page'] or '(home)':40} {r['requests']:4d} {kb(r['raw'])} {kb(r['wire'])}  "
        line += f"{','.join(r['math']) or '-':7} "
        if old_math:
            old = r["wire"] - r["math_wire"] + old_math
            line += f"{kb(old)} {r['wire'] / old:8.2f}"
        print(line)
    total = sum(r["wire"] for r in rows)
    print(f"{'all pages':40} {'':4} {'':11} {kb(total)}")
    if old_math:
        old_total = sum(r["wire"] - r["math_wire"] + old_math for r in rows)
        print(
            f"old design (MathJax on every page, {kb(old_math).strip()} gzipped): "
            f"{kb(old_total).strip()} for all pages; now {total / old_total:.2f} of that"
        )
    else:
        print("old design: the MathJax bundle is not in this repository's git history; no ratio")
    print("Goals:")
    by_page = {r["page"]: r for r in rows}
    for page, goal in GOALS.items():
        r = by_page.get(page)
        if r is None:
            print(f"  {page or '(home)'}: not built")
            continue
        verdict = "met" if r["wire"] <= goal else "NOT met"
        print(f"  {page or '(home)':14} {kb(r['wire'])} of at most {kb(goal).strip()}: {verdict}")


if __name__ == "__main__":
    main()
