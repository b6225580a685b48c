"""Write the class report: a CSV (one row per student and exercise) and one HTML page.

The page is self-contained (its style inline, its charts inline SVG, nothing loaded from
anywhere) and prints on A4: per exercise, how many got it right, the most common slips
with their counts and the hint each got, and a bar chart; per student, a row of ✓ and ✗
with the slips; and one line for each notebook that could not be reported.

>>> from trinormal.notebooks.report import Check, Outcome
>>> right = Check("01-area", "correct", "", "0.866", "correct.")
>>> ok = Outcome("ana.ipynb", "Ana", "ok", checks=(right,))
>>> rows = csv_rows([ok, Outcome("bo.ipynb", "Bo", "timeout", "still running after 5 s")])
>>> [(r["student"], r["exercise"], r["result"]) for r in rows]
[('Ana', '01-area', 'right'), ('Bo', '', 'timeout')]
"""

from __future__ import annotations

import csv
import html
from collections import Counter
from collections.abc import Sequence
from pathlib import Path

from trinormal.exercises import STATUS_COLORS
from trinormal.exercises.judging import SLIPS
from trinormal.notebooks.report import Check, Outcome

__all__ = ["CSV_COLUMNS", "csv_rows", "render_html", "write_csv"]

#: The CSV's columns, in order.
CSV_COLUMNS = ("student", "notebook", "exercise", "variant", "result", "slip", "answer", "message")
#: A verdict's status as the report words it.
RESULTS = {
    "correct": "right",
    "incorrect": "wrong",
    "unanswered": "unanswered",
    "unknown": "unknown-exercise",
}
#: How many slips an exercise's section lists (the rest are counted under "other").
TOP_SLIPS = 5


def csv_rows(outcomes: Sequence[Outcome]) -> list[dict[str, str]]:
    """One row per student and exercise; one row (no exercise) for a notebook not reported."""
    rows = []
    for o in outcomes:
        notebook = Path(o.path).name
        if o.status != "ok":
            rows.append(
                dict.fromkeys(CSV_COLUMNS, "")
                | {
                    "student": o.student,
                    "notebook": notebook,
                    "result": o.status,
                    "message": o.note,
                }
            )
            continue
        for c in o.checks:
            rows.append(
                {
                    "student": o.student,
                    "notebook": notebook,
                    "exercise": c.exercise,
                    "variant": "" if c.variant is None else str(c.variant),
                    "result": RESULTS.get(c.status, c.status),
                    "slip": c.slip,
                    "answer": c.answer,
                    "message": c.message,
                }
            )
    return rows


def write_csv(outcomes: Sequence[Outcome], path: Path) -> None:
    """Write `csv_rows` to ``path`` (UTF-8, a header row first)."""
    with open(path, "w", newline="", encoding="utf-8") as out:
        writer = csv.DictWriter(out, fieldnames=CSV_COLUMNS)
        writer.writeheader()
        writer.writerows(csv_rows(outcomes))


#: The colour of a wrong answer's mark as text: the verdict's orange darkened to a contrast of
#: 4.5:1 on white (the orange itself, 3.9:1, is for the bars, graphics needing 3:1).
WRONG_TEXT = "#A84B00"
_COLOURS = (
    f":root {{ --right: {STATUS_COLORS['correct']}; --wrong: {WRONG_TEXT}; "
    f"--blank: {STATUS_COLORS['unanswered']}; }}"
)
_CSS = """
body { font: 15px/1.45 system-ui, sans-serif; color: #1a1a1a; background: #fff;
  max-width: 60rem; margin: 1.5rem auto; padding: 0 1rem; }
h1 { font-size: 1.6rem; margin-bottom: .2rem; }
h2 { font-size: 1.25rem; border-bottom: 2px solid #ccc; margin-top: 2rem; }
h3 { font-size: 1.05rem; margin: 0 0 .3rem; }
section.exercise { border: 1px solid #ccc; border-radius: 6px; padding: .7rem 1rem;
  margin: .8rem 0; break-inside: avoid; }
table { border-collapse: collapse; width: 100%; table-layout: fixed; }
th, td { text-align: left; vertical-align: top; padding: .25rem .4rem;
  border-bottom: 1px solid #ddd; overflow-wrap: anywhere; }
th { background: #f2f2f2; }
col.count { width: 4.5rem; } col.slip { width: 30%; }
col.name { width: 11rem; } col.right { width: 5rem; }
tr { break-inside: avoid; }
.mark { display: inline-block; margin: 0 .5rem .15rem 0; white-space: nowrap; }
.mark.ok { color: var(--right); } .mark.no { color: var(--wrong); }
.mark.blank { color: var(--blank); }
.mark em { color: #444; font-style: normal; font-size: .85em; }
svg.bars { width: 100%; height: auto; max-width: 40rem; display: block; margin: .3rem 0 .5rem; }
svg.bars text { font: 12px system-ui, sans-serif; fill: #1a1a1a; }
.problems li { margin-bottom: .2rem; }
code { font-size: .9em; }
@page { size: A4; margin: 14mm; }
@media print {
  body { font-size: 10.5pt; max-width: none; margin: 0; padding: 0; }
  section.exercise { border-color: #999; }
  h2 { break-after: avoid; }
  a { color: inherit; text-decoration: none; }
}
"""


def _e(text: object) -> str:
    return html.escape(str(text), quote=True)


def _bars(title: str, bars: Sequence[tuple[str, int, str]], total: int) -> str:
    """Draw a horizontal bar chart in inline SVG, each bar's number written beside it."""
    row, label_w, bar_w = 22, 190, 260
    height = row * len(bars) + 6
    parts = [
        f'<svg class="bars" role="img" viewBox="0 0 {label_w + bar_w + 60} {height}" '
        f'xmlns="http://www.w3.org/2000/svg"><title>{_e(title)}</title>'
    ]
    for i, (label, count, colour) in enumerate(bars):
        y = 4 + i * row
        width = 0 if total == 0 else round(bar_w * count / total, 1)
        parts.append(
            f'<text x="{label_w - 6}" y="{y + 14}" text-anchor="end">{_e(label)}</text>'
            f'<rect x="{label_w}" y="{y}" width="{width}" height="{row - 6}" fill="{colour}"/>'
            f'<text x="{label_w + width + 5}" y="{y + 14}">{count}</text>'
        )
    parts.append("</svg>")
    return "".join(parts)


def _exercise_section(name: str, checks: Sequence[Check]) -> str:
    right = sum(c.status == "correct" for c in checks)
    blank = sum(c.status == "unanswered" for c in checks)
    wrong = [c for c in checks if c.status == "incorrect"]
    slips = Counter(c.slip or "other" for c in wrong)
    hints: dict[str, str] = {}
    for c in wrong:
        hints.setdefault(c.slip or "other", c.message.removeprefix("not yet.").strip())
    common = slips.most_common(TOP_SLIPS)
    rest = sum(slips.values()) - sum(n for _, n in common)
    bars = [("right", right, STATUS_COLORS["correct"])]
    bars += [(slip, n, STATUS_COLORS["incorrect"]) for slip, n in common]
    if rest:
        bars.append(("other slips", rest, STATUS_COLORS["incorrect"]))
    if blank:
        bars.append(("not answered", blank, STATUS_COLORS["unanswered"]))
    summary = f"{right} of {len(checks)} right"
    summary += f", {len(wrong)} wrong" + (f", {blank} not answered" if blank else "")
    chart_title = f"{name}: {summary}; " + "; ".join(f"{s}: {n}" for s, n in common)
    out = [
        f'<section class="exercise" aria-labelledby="ex-{_e(name)}">',
        f'<h3 id="ex-{_e(name)}"><code>{_e(name)}</code></h3><p>{_e(summary)}</p>',
        _bars(chart_title, bars, len(checks)),
    ]
    if common:
        out.append(
            '<table><colgroup><col class="slip"><col class="count"><col></colgroup>'
            '<thead><tr><th scope="col">Slip</th><th scope="col">Count</th>'
            '<th scope="col">Hint they got</th></tr></thead><tbody>'
        )
        for slip, n in common:
            meaning = SLIPS.get(slip, "a wrong answer matching no known slip")
            out.append(
                f"<tr><td><code>{_e(slip)}</code><br>{_e(meaning)}</td><td>{n}</td>"
                f"<td>{_e(hints[slip])}</td></tr>"
            )
        out.append("</tbody></table>")
    out.append("</section>")
    return "".join(out)


def _mark(c: Check) -> str:
    if c.status == "correct":
        return f'<span class="mark ok">✓ {_e(c.exercise)}</span>'
    if c.status == "unanswered":
        return f'<span class="mark blank">– {_e(c.exercise)} <em>not answered</em></span>'
    slip = c.slip or ("unknown exercise" if c.status == "unknown" else "other")
    return f'<span class="mark no">✗ {_e(c.exercise)} <em>{_e(slip)}</em></span>'


def _students_table(outcomes: Sequence[Outcome]) -> str:
    by_student: dict[str, list[Check]] = {}
    for o in outcomes:
        if o.status == "ok":
            by_student.setdefault(o.student, []).extend(o.checks)
    out = [
        '<table class="students"><colgroup><col class="name"><col class="right"><col></colgroup>'
        '<thead><tr><th scope="col">Student</th><th scope="col">Right</th>'
        '<th scope="col">Exercises (✓ right, ✗ wrong with the slip, – not answered)</th>'
        "</tr></thead><tbody>"
    ]
    for student in sorted(by_student, key=str.casefold):
        checks = by_student[student]
        right = sum(c.status == "correct" for c in checks)
        marks = " ".join(_mark(c) for c in sorted(checks, key=lambda c: c.exercise))
        out.append(
            f'<tr><th scope="row">{_e(student)}</th><td>{right} of {len(checks)}</td>'
            f"<td>{marks}</td></tr>"
        )
    out.append("</tbody></table>")
    return "".join(out)


def render_html(outcomes: Sequence[Outcome], title: str = "Class report") -> str:
    """Render the whole report as one self-contained HTML page."""
    reported = [o for o in outcomes if o.status == "ok"]
    by_exercise: dict[str, list[Check]] = {}
    for o in reported:
        for c in o.checks:
            if c.status != "unknown":
                by_exercise.setdefault(c.exercise, []).append(c)
    students = {o.student for o in reported}
    problems = [o for o in outcomes if o.status != "ok"]
    head = (
        f"{len(outcomes)} notebook{'s' * (len(outcomes) != 1)} handed in, "
        f"{len(reported)} reported for {len(students)} student{'s' * (len(students) != 1)}, "
        f"{len(by_exercise)} exercise{'s' * (len(by_exercise) != 1)}."
    )
    body = [f"<h1>{_e(title)}</h1><p>{_e(head)}</p>"]
    if problems:
        body.append('<h2 id="problems">Not reported</h2><ul class="problems">')
        for o in problems:
            body.append(
                f"<li><strong>{_e(o.student)}</strong> ({_e(Path(o.path).name)}): "
                f"{_e(o.status)}: {_e(o.note)}</li>"
            )
        body.append("</ul>")
    body.append('<h2 id="exercises">Exercises</h2>')
    body += [_exercise_section(n, by_exercise[n]) for n in sorted(by_exercise)]
    body.append('<h2 id="students">Students</h2>')
    body.append(_students_table(reported))
    return _page(title, _COLOURS + _CSS, "".join(body))


def _page(title: str, css: str, body: str) -> str:
    """Wrap ``body`` in a self-contained HTML page, its style inline (a worksheet's too)."""
    return (
        '<!DOCTYPE html>\n<html lang="en"><head><meta charset="utf-8">'
        '<meta name="viewport" content="width=device-width, initial-scale=1">'
        f"<title>{_e(title)}</title><style>{css}</style></head>"
        f"<body><main>{body}</main></body></html>\n"
    )
