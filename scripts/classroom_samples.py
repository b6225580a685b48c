"""Make the "For teachers" page's samples and screenshots from the generated sample class.

Usage: ``.venv/bin/python scripts/classroom_samples.py``. It writes the sample class
(`trinormal.notebooks.sample`) to a temporary folder, runs ``trinormal-notebooks report``
on it, makes worksheets for a three-name roster, and saves into ``docs/assets/teachers/``
the report (HTML and CSV), one worksheet and its answer key, then photographs the report
and the worksheet in Debian's Chromium into ``docs/assets/images/teachers-report.png``
and ``teachers-worksheet.png``. Run it again whenever the report or the worksheets
change (tests/test_classroom.py fails when the committed sample report is stale).
"""

from __future__ import annotations

import sys
import tempfile
from pathlib import Path

ROOT = Path(__file__).resolve().parents[1]
sys.path.insert(0, str(ROOT / "tests" / "browser"))

from browser_support import CHROMIUM, CHROMIUM_ARGS  # type: ignore[import-not-found]  # noqa: E402
from explorer_screenshot import save_in_64_colours  # noqa: E402  (scripts/, this script's folder)

from trinormal.notebooks import main  # noqa: E402
from trinormal.notebooks.sample import SAMPLE_ROSTER, SAMPLE_TIMEOUT, write_sample_class  # noqa: E402

OUT = ROOT / "docs" / "assets" / "teachers"
IMAGES = ROOT / "docs" / "assets" / "images"


def _photograph(page_file: Path, png: Path, height: int) -> None:
    """Save the top ``height`` CSS pixels of a page, 800 wide, drawn at 1.5x, in 64 colours."""
    from playwright.sync_api import sync_playwright

    with sync_playwright() as p:
        browser = p.chromium.launch(executable_path=CHROMIUM, args=CHROMIUM_ARGS, headless=True)
        try:
            page = browser.new_page(
                viewport={"width": 800, "height": height}, device_scale_factor=1.5
            )
            page.goto(page_file.as_uri())
            shot = page.screenshot()
        finally:
            browser.close()
    save_in_64_colours(shot, png)


def main_samples() -> None:
    """Write the samples and the two screenshots."""
    OUT.mkdir(parents=True, exist_ok=True)
    with tempfile.TemporaryDirectory() as tmp:
        folder = Path(tmp)
        write_sample_class(folder / "class")
        status = main(
            [
                "report",
                str(folder / "class"),
                "--timeout",
                str(SAMPLE_TIMEOUT),
                "--html",
                str(OUT / "sample-report.html"),
                "--csv",
                str(OUT / "sample-report.csv"),
            ]
        )
        if status:
            raise SystemExit(status)
        roster = folder / "roster.txt"
        roster.write_text("\n".join(SAMPLE_ROSTER) + "\n", encoding="utf-8")
        sheets = folder / "sheets"
        if main(["worksheet", "--students", str(roster), "--out", str(sheets)]):
            raise SystemExit(2)
        (OUT / "sample-worksheet.html").write_bytes((sheets / "ana-lima.html").read_bytes())
        (OUT / "sample-answer-key.html").write_bytes((sheets / "answer-key.html").read_bytes())
    _photograph(OUT / "sample-report.html", IMAGES / "teachers-report.png", 900)
    _photograph(OUT / "sample-worksheet.html", IMAGES / "teachers-worksheet.png", 900)


if __name__ == "__main__":
    main_samples()
