"""The class report and a worksheet in Chromium: accessible, self-contained, printable on A4.

The pages are the docs' samples (``docs/assets/teachers/``), which tests/test_classroom.py
keeps equal to a fresh report of the generated sample class.
"""

from __future__ import annotations

import re

from page_checks import run_axe, settle

#: An A4 page's printable width in CSS pixels (210 mm less the 14 mm margins, at 96 per inch).
A4_PRINT_WIDTH = round((210 - 2 * 14) / 25.4 * 96)

_OVERFLOW = """() => {
  const width = document.documentElement.clientWidth;
  return [...document.querySelectorAll("main, section, table, tr, svg, li, p, code")]
    .filter(e => e.getBoundingClientRect().right > width + 0.5 || e.scrollWidth > e.clientWidth + 1)
    .map(e => e.outerHTML.slice(0, 90));
}"""

_UNBROKEN = """() => [...document.querySelectorAll("tr, section.exercise, section.item, ol.tasks > li")]
  .filter(e => getComputedStyle(e).breakInside !== "avoid").map(e => e.outerHTML.slice(0, 90))"""


def test_the_report_and_a_worksheet_are_axe_clean_and_print_on_a4(page, server, traffic):
    for name in ("sample-report.html", "sample-worksheet.html"):
        page.emulate_media(media="screen")
        page.set_viewport_size({"width": 1280, "height": 800})
        page.goto(f"{server}assets/teachers/{name}")
        settle(page)
        results = run_axe(page)
        assert results.response["passes"], f"{name}: axe checked nothing"
        assert results.response["violations"] == [], (name, results.response["violations"])

        page.emulate_media(media="print")
        page.set_viewport_size({"width": A4_PRINT_WIDTH, "height": 1000})
        assert page.evaluate(_OVERFLOW) == [], f"{name}: wider than an A4 page"
        assert page.evaluate(_UNBROKEN) == [], f"{name}: a row or block a page break could cut"
        pdf = page.pdf(prefer_css_page_size=True)
        assert pdf.startswith(b"%PDF")
        sizes = set(re.findall(rb"/MediaBox\s*\[\s*0 0 ([\d.]+) ([\d.]+)\s*\]", pdf))
        assert {(round(float(w)), round(float(h))) for w, h in sizes} == {(595, 842)}, name
    assert traffic.requests and not traffic.problems()
