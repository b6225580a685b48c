"""Photograph the live 3D explorer on the built site for the home page and the README.

Usage: ``make docs-build`` first, then ``.venv/bin/python scripts/explorer_screenshot.py``.
It serves ``site/`` on 127.0.0.1, opens the calculator page in Debian's Chromium at a
phone's width (400 CSS pixels, drawn at 2x), and saves the 3D view, its toolbar and its
instructions to ``docs/assets/images/explorer-3d.png`` (64 colours, about 35 KB). Run it
again whenever the view changes, so the picture never goes stale.
"""

from __future__ import annotations

import io
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "browser"))

from browser_support import (  # type: ignore[import-not-found]  # noqa: E402
    CHROMIUM,
    CHROMIUM_ARGS,
    serve_site,
)

OUT = ROOT / "docs" / "assets" / "images" / "explorer-3d.png"
QUERY = "?a=0,0,0&b=2,0,0&c=0,1,1&w=ABC&p=4"


def save_in_64_colours(shot: bytes, path: Path) -> None:
    """Save a browser's screenshot (PNG bytes) in 64 colours, as the docs' pictures are kept."""
    from PIL import Image

    image = Image.open(io.BytesIO(shot)).convert("RGB")
    image.quantize(colors=64, method=Image.Quantize.MEDIANCUT).save(path, optimize=True)
    print(f"{path.relative_to(ROOT)}: {image.width} x {image.height} pixels")


def main() -> None:
    """Render the calculator's live 3D view in Chromium and save it as the home page picture."""
    from playwright.sync_api import sync_playwright

    with serve_site(ROOT / "site") as url, sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS, headless=True)
        try:
            page = browser.new_page(viewport={"width": 400, "height": 900}, device_scale_factor=2)
            page.goto(url.rstrip("/") + "/calculator/" + QUERY)
            page.wait_for_selector("#tn-calculator[data-ready='true']")
            page.wait_for_selector("#tn-view[data-ready='true']")
            view = page.locator("#tn-view")
            view.evaluate("v => v.scrollIntoView({block: 'center'})")
            page.wait_for_timeout(800)
            png = view.screenshot()
        finally:
            browser.close()
    save_in_64_colours(png, OUT)


if __name__ == "__main__":
    main()
