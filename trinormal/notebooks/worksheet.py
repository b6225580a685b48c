"""Worksheets with each student's own numbers, and the teacher's answer key.

``trinormal-notebooks worksheet --students roster.txt --out DIR`` writes one printable
HTML page per student (their name, the exercises with their numbers, room to work)
and ``answer-key.html`` with every student's answers and the worked steps from
`trinormal.steps`. The variants come from `trinormal.exercises.variants.assign`: the
same roster and seed give the same pages, and no two students share a variant of an
exercise while the bank has enough. Each page prints the line that gives the student
the same numbers in a notebook, ``exercises.student("Ana Lima", code="…")``.

>>> pages, key = worksheets(["Ana Lima", "Ben Okafor"], ["01-normal", "01-area"], seed=1)
>>> sorted(pages)
['ana-lima.html', 'ben-okafor.html']
>>> "Ben Okafor" in key and "B − A = (" in key
True
"""

from __future__ import annotations

import html
import json
import re
from collections.abc import Sequence
from fractions import Fraction
from pathlib import Path
from typing import Any

from trinormal.core import triangle_normal
from trinormal.display import exact_text, format_number, radical_text
from trinormal.exercises import Exercise, point_text
from trinormal.exercises.variants import TEMPLATES, assign, group_of, student_code
from trinormal.notebooks.class_report import _page
from trinormal.steps import steps, working

__all__ = ["answer_text", "notebook_line", "read_roster", "worked_steps", "worksheets"]

_CSS = """
body { font: 15px/1.45 system-ui, sans-serif; color: #1a1a1a; background: #fff;
  max-width: 46rem; margin: 1.5rem auto; padding: 0 1rem; }
h1 { font-size: 1.5rem; margin-bottom: .2rem; }
h2 { font-size: 1.2rem; margin-top: 1.6rem; border-bottom: 2px solid #ccc; }
ol.tasks > li { margin: 0 0 1rem; break-inside: avoid; }
.work { border: 1px solid #888; border-radius: 4px; min-height: 6.5rem; margin: .4rem 0; }
.answer { margin: .2rem 0 0; }
.answer span { display: inline-block; min-width: 18rem; border-bottom: 1px solid #444; }
code { font-size: .9em; overflow-wrap: anywhere; }
table { border-collapse: collapse; width: 100%; table-layout: fixed; }
th, td { text-align: left; vertical-align: top; padding: .2rem .4rem; border-bottom: 1px solid #ddd;
  overflow-wrap: anywhere; }
th { width: 6rem; }
section.student { break-before: page; }
section.student:first-of-type { break-before: auto; }
section.item { break-inside: avoid; margin-bottom: .8rem; }
@page { size: A4; margin: 15mm; }
@media print { body { max-width: none; margin: 0; padding: 0; font-size: 11pt; } }
"""


def read_roster(path: Path) -> list[str]:
    """Read a roster: one name a line; blank lines and lines starting with ``#`` are skipped.

    Raises
    ------
    ValueError
        When it names nobody (the message names the file).
    """
    names = []
    for line in path.read_text(encoding="utf-8").splitlines():
        name = " ".join(line.split())
        if name and not name.startswith("#"):
            names.append(name)
    if not names:
        raise ValueError(f"{path}: the roster names nobody (one name a line)")
    return names


def _slug(name: str) -> str:
    return re.sub(r"[^\w]+", "-", name.casefold()).strip("-") or "student"


def answer_text(value: Any) -> str:
    """Write an answer as the key shows it (and as ``check`` reads it).

    Examples
    --------
    >>> answer_text((Fraction(-6), Fraction(1, 2), 7)), answer_text(5.5), answer_text(Fraction(4))
    ('(-6, 0.5, 7)', '5.5', '4')
    """
    if isinstance(value, tuple | list):
        return point_text([answer_text(x) for x in value])
    if isinstance(value, float):
        return format_number(value, 6, trim=True)
    if isinstance(value, Fraction | int):
        return exact_text(Fraction(value))
    return str(value)


def worked_steps(name: str, numbers: Any) -> list[tuple[str, str]]:
    """Write out one variant's worked steps, from `trinormal.steps` (and the exercise's own).

    Examples
    --------
    >>> worked_steps("05-scale-area", (((0, 0, 0), (2, 0, 0), (0, 1, 0)), 3))[-1]
    ('factor', 'area(kA, kB, kC) / area(A, B, C) = √81 = 9 = k²')
    """
    if name.startswith("01-"):
        winding = "ACB" if name == "01-reversed" else "ABC"
        a, b, c = numbers
        return steps(triangle_normal(a, b, c, winding=winding))
    if name == "02-lagrange":
        u, v = numbers
        w = working(triangle_normal((0, 0, 0), u, v))
        dot = sum((a * b for a, b in zip(u, v, strict=True)), Fraction(0))
        uu, vv = (sum((Fraction(a) ** 2 for a in x), Fraction(0)) for x in (u, v))
        return [
            ("|U|²", exact_text(uu)),
            ("|V|²", exact_text(vv)),
            ("U · V", exact_text(dot)),
            (
                "|N|²",
                f"|U|²|V|² − (U · V)² = {exact_text(uu * vv)} − {exact_text(dot**2)} "
                f"= {exact_text(w.magnitude_squared)}",
            ),
        ]
    if name == "04-dot-value":
        w = working(triangle_normal(*numbers))
        dot = sum((a * b for a, b in zip(w.u, w.v, strict=True)), Fraction(0))
        lines = steps(triangle_normal(*numbers))[:2]
        return [*lines, ("U · V", f"UxVx + UyVy + UzVz = {exact_text(dot)}")]
    if name == "04-2d-nz":
        p, q, r = ((*pt, 0) for pt in numbers)
        return [s for s in steps(triangle_normal(p, q, r)) if s[0] in ("U", "V", "Nz")]
    if name == "05-scale-area":
        abc, k = numbers
        before = working(triangle_normal(*abc))
        ka, kb, kc = (tuple(k * x for x in p) for p in abc)
        after = working(triangle_normal(ka, kb, kc))
        ratio = after.magnitude_squared / before.magnitude_squared
        return [
            ("area", f"|N| / 2 = {radical_text(before.root / 2, before.radicand)} before scaling"),
            ("factor", f"area(kA, kB, kC) / area(A, B, C) = √{exact_text(ratio)} = {k * k} = k²"),
        ]
    if name == "05-collinear":
        a, b = (tuple(Fraction(x) for x in p) for p in numbers)
        c = tuple(p + (q - p) / 3 for p, q in zip(a, b, strict=True))
        return [("C", f"A + (B − A) / 3 = {point_text(c)}: any A + t (B − A), t ≠ 0, 1")]
    return []


def notebook_line(student: str, code: str) -> str:
    """Write the line that gives a student the worksheet's numbers in a notebook.

    Examples
    --------
    >>> print(notebook_line("Ana Lima", "1.2.3.4.5.6"))
    exercises.student("Ana Lima", code="1.2.3.4.5.6")
    """
    return f"exercises.student({json.dumps(student, ensure_ascii=False)}, code={json.dumps(code)})"


def _task_html(ex: Exercise) -> str:
    return (
        f"<li><p><strong><code>{html.escape(ex.name)}</code></strong>: {html.escape(ex.prompt)}</p>"
        '<div class="work"></div>'
        '<p class="answer">Answer: <span>&nbsp;</span></p></li>'
    )


def worksheets(
    roster: Sequence[str], names: Sequence[str], seed: int = 0
) -> tuple[dict[str, str], str]:
    """Make every student's page and the answer key.

    Parameters
    ----------
    roster : sequence of str
        The students' names, one each.
    names : sequence of str
        The exercises, each one that has variants (``variants.variant_names()``).
    seed : int
        Another seed gives other variants.

    Returns
    -------
    pages : dict
        ``{file name: HTML}``, one page per student.
    key : str
        The answer key's HTML.
    """
    chosen = assign(roster, seed)
    banks = {t.group: t.numbers() for t in TEMPLATES}  # drawn once for the whole class

    def own(student: str, name: str) -> tuple[Exercise, Any]:
        template = group_of(name)
        if template is None:
            raise ValueError(f"exercise {name!r} has no variants")
        numbers = banks[template.group][chosen[student][template.group]]
        return template.build(numbers)[template.names.index(name)], numbers

    pages: dict[str, str] = {}
    key = [f"<h1>Answer key</h1><p>{len(roster)} students, seed {seed}.</p>"]
    for student in roster:
        code = student_code(chosen[student])
        items = [own(student, n) for n in names]
        body = (
            f"<h1>Worksheet: {html.escape(student)}</h1>"
            "<p>Your own numbers. In a notebook, run once at the top: "
            f"<code>{html.escape(notebook_line(student, code))}</code></p>"
            '<ol class="tasks">' + "".join(_task_html(ex) for ex, _ in items) + "</ol>"
        )
        file = f"{_slug(student)}.html"
        while file in pages:
            file = file.removesuffix(".html") + "-2.html"
        pages[file] = _page(f"Worksheet: {student}", _CSS, body)
        key.append(f'<section class="student"><h2>{html.escape(student)}</h2>')
        key.append(f"<p>Code <code>{html.escape(code)}</code></p>")
        for ex, numbers in items:
            rows = "".join(
                f"<tr><th scope='row'>{html.escape(label)}</th><td>{html.escape(text)}</td></tr>"
                for label, text in worked_steps(ex.name, numbers)
            )
            key.append(
                f'<section class="item"><h3><code>{html.escape(ex.name)}</code>: '
                f"{html.escape(answer_text(ex.solution()))}</h3>"
                f"<p>{html.escape(ex.prompt)}</p><table>{rows}</table></section>"
            )
        key.append("</section>")
    return pages, _page("Answer key", _CSS, "".join(key))
