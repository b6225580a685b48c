"""The teacher's tools: slip codes, students' variants, worksheets and the class report.

The class report runs the generated sample class (`trinormal.notebooks.sample`) for real:
one kernel per notebook, two at a time, with the sample's short time limit.
"""

from __future__ import annotations

import csv
import json
import subprocess
import sys
import zipfile
from fractions import Fraction
from pathlib import Path

import pytest

from trinormal.exercises import Student, check, get, names, task
from trinormal.exercises.judging import SLIPS
from trinormal.exercises.variants import (
    BANK_SIZE,
    TEMPLATES,
    assign,
    read_code,
    variant_exercise,
    variant_names,
)
from trinormal.notebooks import main
from trinormal.notebooks.report import collect, student_name
from trinormal.notebooks.sample import SAMPLE_TIMEOUT, write_sample_class
from trinormal.notebooks.worksheet import answer_text, worksheets

ROOT = Path(__file__).resolve().parents[1]
SAMPLE_REPORT = ROOT / "docs" / "assets" / "teachers" / "sample-report.html"

#: What the sample class must give: (student, notebook, exercise, variant, result, slip).
EXPECTED = [
    ("Ana Lima", "ana_lima.ipynb", "01-normal", "", "right", ""),
    ("Ana Lima", "ana_lima.ipynb", "01-area", "", "right", ""),
    ("Ana Lima", "ana_lima.ipynb", "01-reversed", "", "right", ""),
    ("Ana Lima", "ana_lima.ipynb", "04-dot-value", "", "right", ""),
    ("Ana Lima", "ana_lima.ipynb", "05-scale-area", "", "right", ""),
    ("Ana Lima", "ana_lima.ipynb", "05-down-acb", "", "right", ""),
    ("Ana Lima", "ana_lima.ipynb", "04-2d-nz", "", "unanswered", ""),
    ("Ben Okafor", "ben_okafor.ipynb", "01-normal", "", "wrong", "reversed-order"),
    ("Ben Okafor", "ben_okafor.ipynb", "01-area", "", "wrong", "magnitude-for-area"),
    ("Ben Okafor", "ben_okafor.ipynb", "01-reversed", "", "wrong", "reversed-order"),
    ("Ben Okafor", "ben_okafor.ipynb", "04-dot-value", "", "wrong", "cross-for-dot"),
    ("Ben Okafor", "ben_okafor.ipynb", "05-scale-area", "", "wrong", "linear-scaling"),
    ("Ben Okafor", "ben_okafor.ipynb", "05-down-acb", "", "wrong", "reversed-order"),
    ("Cleo Diaz", "cleo_diaz.ipynb", "01-normal", "", "wrong", "unit-for-raw"),
    ("Cleo Diaz", "cleo_diaz.ipynb", "01-area", "", "wrong", "half-area"),
    ("Cleo Diaz", "cleo_diaz.ipynb", "05-scale-area", "", "wrong", "cubic-scaling"),
    ("Cleo Diaz", "cleo_diaz.ipynb", "05-down-acb", "", "wrong", "degenerate"),
    ("Dara Novak", "dara_novak.ipynb", "01-area", "", "wrong", "squared-magnitude"),
    ("Dara Novak", "dara_novak.ipynb", "05-scale-area", "", "wrong", "inverse-factor"),
    ("Dara Novak", "dara_novak.ipynb", "05-down-acb", "", "wrong", "tilted"),
    ("Farah Haddad", "farah_haddad_01_worked_example.ipynb", "01-normal", "51", "right", ""),
    ("Farah Haddad", "farah_haddad_01_worked_example.ipynb", "01-area", "51", "right", ""),
    ("Farah Haddad", "farah_haddad_01_worked_example.ipynb", "05-scale-area", "31", "right", ""),
    (
        "Farah Haddad",
        "farah_haddad_01_worked_example.ipynb",
        "01-reversed",
        "51",
        "wrong",
        "reversed-order",
    ),
    ("gus moreau", "gus_moreau.ipynb", "", "", "failed", ""),
    ("hana sato", "hana_sato.ipynb", "", "", "timeout", ""),
    ("holiday photos", "holiday_photos.ipynb", "", "", "not-ours", ""),
    ("ivo petrov", "ivo_petrov.ipynb", "01-nromal", "", "unknown-exercise", ""),
    ("ivo petrov", "ivo_petrov.ipynb", "01-area", "", "right", ""),
]


def test_the_sample_class_gives_the_expected_csv_and_the_docs_sample_report(tmp_path, capsys):
    write_sample_class(tmp_path / "class")
    out_csv, out_html = tmp_path / "report.csv", tmp_path / "report.html"
    status = main(
        [
            "report",
            str(tmp_path / "class"),
            "--timeout",
            str(SAMPLE_TIMEOUT),
            "--jobs",
            "2",
            "--csv",
            str(out_csv),
            "--html",
            str(out_html),
        ]
    )
    assert status == 0
    with open(out_csv, encoding="utf-8") as f:
        rows = list(csv.DictReader(f))
    got = [
        tuple(r[k] for k in ("student", "notebook", "exercise", "variant", "result", "slip"))
        for r in rows
    ]
    assert got == EXPECTED
    by_key = {(r["student"], r["exercise"]): r for r in rows}
    assert by_key["Ana Lima", "01-area"]["answer"] == "0,866"
    assert by_key["gus moreau", ""]["message"] == (
        "stopped at cell 3: ZeroDivisionError: division by zero"
    )
    assert by_key["hana sato", ""]["message"].startswith(f"still running after {SAMPLE_TIMEOUT} s")
    progress = capsys.readouterr().out
    assert progress.count("] ") == 9 and "[9/9]" in progress
    # The docs' sample report is this very report: rerun scripts/classroom_samples.py if not.
    assert out_html.read_text(encoding="utf-8") == SAMPLE_REPORT.read_text(encoding="utf-8")


def test_the_report_help_says_the_students_code_runs_here(capsys):
    with pytest.raises(SystemExit):
        main(["report", "--help"])
    assert "runs the students' code on this machine" in " ".join(capsys.readouterr().out.split())


def test_report_without_notebooks_says_so_in_one_line(tmp_path, capsys):
    (tmp_path / "notes.txt").write_text("hello")
    assert main(["report", str(tmp_path / "notes.txt"), str(tmp_path / "missing")]) == 2
    err = capsys.readouterr().err.splitlines()
    assert err == [
        f"trinormal-notebooks report: {tmp_path / 'notes.txt'}: not a notebook, a folder or a zip file",
        f"trinormal-notebooks report: {tmp_path / 'missing'}: no such file or folder",
        "trinormal-notebooks report: no notebook to run",
    ]


def test_report_without_nbclient_names_the_extra(tmp_path):
    code = (
        "import sys\nsys.modules['nbclient'] = None\n"
        "from trinormal.notebooks import main\n"
        f"sys.exit(main(['report', {str(tmp_path)!r}]))"
    )
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True)
    assert done.returncode == 2
    assert done.stderr == (
        "trinormal-notebooks report: running notebooks needs nbclient: "
        'pip install "trinormal[notebooks]"\n'
    )


def test_a_zip_from_an_lms_is_unpacked_inside_its_folder_only(tmp_path):
    archive = tmp_path / "handed-in.zip"
    with zipfile.ZipFile(archive, "w") as zf:
        zf.writestr("Ben Okafor/01_worked_example.ipynb", "{}")
        zf.writestr("../../escape.ipynb", "{}")
        zf.writestr("__MACOSX/Ben Okafor/._01_worked_example.ipynb", "")
        zf.writestr("readme.txt", "")
    found, problems = collect([archive], tmp_path / "unpacked")
    assert problems == []
    assert sorted(p.relative_to(tmp_path / "unpacked").as_posix() for p in found) == [
        "000-handed-in/Ben Okafor/01_worked_example.ipynb",
        "000-handed-in/escape.ipynb",
    ]
    assert not (tmp_path / "escape.ipynb").exists()
    assert student_name(found[0]) == "Ben Okafor"


def test_every_listed_mistake_has_a_known_slip_code_and_gets_it():
    for name in names():
        ex = get(name)
        for wrong, _hint, slip in ex.mistakes:
            assert slip in SLIPS, (name, slip)
            value = wrong() if callable(wrong) else wrong
            result = ex.check(value)
            assert (result.status, result.slip) == ("incorrect", slip), (name, value)


def test_general_slips_have_codes_too():
    assert check("01-normal", (0.577, 0.577, 0.577)).slip == "unit-for-raw"
    assert check("01-normal", "(2, 2, 2)").slip == "wrong-length"
    assert check("04-dot-value", -6).slip == "wrong-sign"
    assert check("01-area", [1, 2]).slip == "unreadable"
    assert check("01-area", 0.87).slip == "rounded"
    assert {r.slip for r in (check("01-area", 0.8660254), check("01-area", 1.0))} == {""}


def test_without_a_name_the_exercises_are_the_notebooks_own():
    """The factories rebuild exactly the prompts the notebooks were written against."""
    assert get("01-normal").prompt == (
        "Compute N = (B − A) × (C − A) for A = (1, 0, 0), B = (0, 1, 0), C = (0, 0, 1)."
    )
    assert get("02-lagrange").prompt == (
        "U = (1, 2, 2) and V = (2, 0, 0). Use Lagrange's identity to find |N|² exactly."
    )
    assert get("04-dot-value").prompt.startswith("For A = (0,0,0), B = (2,0,0), C = (3,1,0), what")
    assert get("04-2d-nz").prompt.startswith("The 2D triangle P = (0, 0), Q = (0, 2), R = (3, 0),")
    assert get("05-collinear").prompt.startswith("A = (1, 2, 0) and B = (3, 3, 1). Give a point C")
    assert get("05-scale-area").prompt.startswith(
        "Multiply every coordinate of A = (1, 0, 1), B = (1, 1, 0), C = (-1, 1, 1) by 3."
    )
    assert check("01-normal", (1, 1, 1)).correct and not check("01-normal", (0, 0, 1)).correct


def test_every_variant_is_clean_and_its_slips_are_not_right():
    for template in TEMPLATES:
        built = [template.build(numbers) for numbers in template.numbers()]
        assert len({exs[0].prompt for exs in built}) == BANK_SIZE, template.group
        for index, ex in ((i, ex) for i, exs in enumerate(built) for ex in exs):
            solution = ex.solution()
            values = solution if isinstance(solution, tuple) else (solution,)
            for x in values:  # whole numbers, halves, quarters, thirds: no 17-digit decimals
                q = Fraction(x).limit_denominator(1000)
                assert q.denominator in (1, 2, 3, 4, 6, 8, 9, 12, 16) and Fraction(x) == q
            assert ex.check(answer_text(solution)).correct, (ex.name, index)
            for wrong, _hint, slip in ex.mistakes:
                value = wrong() if callable(wrong) else wrong
                assert ex.check(value).slip == slip, (ex.name, index, value)
    assert variant_exercise("01-area", 5).prompt == built_prompt("01-area", 5)


def built_prompt(name: str, index: int) -> str:
    """The prompt of a variant, built straight from its template's numbers."""
    template = next(t for t in TEMPLATES if name in t.names)
    return template.build(template.numbers()[index])[template.names.index(name)].prompt


def test_worksheets_for_a_class_of_30_are_reproducible_distinct_and_their_key_is_right(tmp_path):
    roster = [f"Student {chr(65 + i // 10)}{i % 10}" for i in range(30)]
    (tmp_path / "roster.txt").write_text("# class 3B\n" + "\n".join(roster) + "\n\n")
    for run in ("a", "b"):
        assert (
            main(
                [
                    "worksheet",
                    "--students",
                    str(tmp_path / "roster.txt"),
                    "--out",
                    str(tmp_path / run),
                    "--seed",
                    "7",
                ]
            )
            == 0
        )
    files = sorted(p.name for p in (tmp_path / "a").iterdir())
    assert len(files) == 31 and "answer-key.html" in files
    for file in files:
        assert (tmp_path / "a" / file).read_bytes() == (tmp_path / "b" / file).read_bytes()
    chosen = assign(roster, seed=7)
    for template in TEMPLATES:
        assert len({chosen[s][template.group] for s in roster}) == 30, template.group
    pages, key = worksheets(roster, variant_names(), seed=7)
    # each group's bank, built once: a student's exercise is the one of their variant
    # (Student.exercise draws the bank again on every call; the first student goes that way)
    built = {t.group: [t.build(numbers) for numbers in t.numbers()] for t in TEMPLATES}
    for student in roster:
        page = pages[student.lower().replace(" ", "-") + ".html"]
        assert 6 <= page.count('class="work"') <= 10 and student in page
        me = Student(student, 7, code=next(c for c in _codes(key) if c[0] == student)[1])
        assert read_code(me.code) == chosen[student]
        for template in TEMPLATES:
            index = me.variant(template.group)
            assert index == chosen[student][template.group]
            for name, exercise in zip(template.names, built[template.group][index], strict=True):
                shown = answer_text(exercise.solution())
                assert exercise.check(shown).correct, (student, name, shown)
                assert f"<code>{name}</code>: {shown}" in key
                if student == roster[0]:
                    assert me.exercise(name).prompt == exercise.prompt
                    assert me.check(name, shown).correct, (student, name, shown)


def _codes(key: str) -> list[tuple[str, str]]:
    """The (student, code) pairs the answer key prints."""
    import re

    return re.findall(r"<h2>([^<]+)</h2><p>Code <code>([0-9.]+)</code>", key)


def test_a_roster_naming_someone_twice_is_refused(tmp_path, capsys):
    (tmp_path / "roster.txt").write_text("Ana Lima\nana  lima\n")
    args = ["worksheet", "--students", str(tmp_path / "roster.txt"), "--out", str(tmp_path / "o")]
    assert main(args) == 2
    assert capsys.readouterr().err == (
        "trinormal-notebooks worksheet: 'Ana Lima' is on the roster twice: "
        "give each student a distinct name\n"
    )
    assert main([*args, "--exercises", "06-float64-bits"]) == 2


def test_a_student_gets_their_own_numbers_and_task_prints_them(capsys):
    ana, ben = Student("Ana Lima"), Student("Ben Okafor")
    assert ana.exercise("01-normal").prompt != ben.exercise("01-normal").prompt
    assert ana.exercise("06-float64-bits") is get("06-float64-bits")
    ana.task("01-normal")
    task("01-normal")
    lines = capsys.readouterr().out.splitlines()
    assert lines == [
        f"01-normal: {ana.exercise('01-normal').prompt}",
        f"01-normal: {get('01-normal').prompt}",
    ]
    with pytest.raises(ValueError, match="not one from a worksheet"):
        Student("Ana", code="1.2").variant("01-area")


def test_check_records_its_verdict_only_for_the_report(tmp_path, monkeypatch):
    log = tmp_path / "checks.jsonl"
    check("01-area", 0.866)
    assert not log.exists()
    monkeypatch.setenv("TRINORMAL_CHECK_LOG", str(log))
    check("01-area", 1.7320508)
    check("01-nromal", 1)
    entries = [json.loads(line) for line in log.read_text().splitlines()]
    assert [(e["exercise"], e["status"], e["slip"], e["answer"]) for e in entries] == [
        ("01-area", "incorrect", "magnitude-for-area", "1.7320508"),
        ("01-nromal", "unknown", "", "1"),
    ]
