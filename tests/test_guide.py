"""The guide's published numbers against the same numbers rebuilt by trinormal."""

from __future__ import annotations

from pathlib import Path

from trinormal import guide, triangle_normal

ROOT = Path(__file__).resolve().parents[1]
SEED = ROOT.parent / "shared" / "seed" / "000_eb5c1a284812b1e1.txt"
TABLE_COPY = Path(__file__).parent / "data" / "guide_comparison_table.md"
EXCERPTS = Path(__file__).parent / "data" / "guide_excerpts.txt"


def table_lines(text: str) -> list[str]:
    """The comparison table's lines: from its header to the last line starting with '|'."""
    lines = text.splitlines()
    start = next(i for i, line in enumerate(lines) if line.startswith("| Triangle vertices"))
    end = start
    while end < len(lines) and lines[end].startswith("|"):
        end += 1
    return lines[start:end]


def guide_table() -> list[str]:
    """The guide's table text: from the seed file when it is there, else the stored copy."""
    source = SEED if SEED.is_file() else TABLE_COPY
    return table_lines(source.read_text(encoding="utf-8"))


def test_table_equals_the_guide_cell_by_cell():
    published = guide.parse_markdown_table("\n".join(guide_table()))
    rebuilt = guide.comparison_table_cells()
    assert len(published) == len(rebuilt) == 5
    for want_row, got_row in zip(published, rebuilt, strict=True):
        assert got_row == want_row


def test_table_markdown_equals_the_guide_text():
    assert guide.comparison_table_markdown() == "\n".join(guide_table())


def test_stored_copy_matches_the_seed():
    copy = table_lines(TABLE_COPY.read_text(encoding="utf-8"))
    assert len(copy) == 6
    if SEED.is_file():
        assert copy == table_lines(SEED.read_text(encoding="utf-8"))


def test_headers_and_published_rows_are_the_guides():
    published = guide.parse_markdown_table("\n".join(guide_table()))
    assert tuple(published[0]) == guide.COMPARISON_HEADERS
    for row, cells in zip(guide.COMPARISON_ROWS, published[1:], strict=True):
        assert [row.normal, row.magnitude, row.area, row.unit_normal] == cells[1:]


def test_each_recomputed_cell_matches_the_published_row():
    for row, cells in zip(guide.COMPARISON_ROWS, guide.comparison_table_cells()[1:], strict=True):
        assert cells[1:] == [row.normal, row.magnitude, row.area, row.unit_normal]


def test_a_changed_cell_is_noticed():
    text = "\n".join(guide_table()).replace("1.4142", "1.4143")
    assert guide.parse_markdown_table(text) != guide.comparison_table_cells()


def test_cells_follow_the_package_not_the_published_strings(monkeypatch):
    row = guide.COMPARISON_ROWS[2]
    moved = guide.ComparisonRow((1, 1, 1), (3, 1, 1), (1, 2, 2), "", "", "", "")
    monkeypatch.setattr(guide, "COMPARISON_ROWS", (row, moved))
    cells = guide.comparison_table_cells()
    r = triangle_normal(moved.a, moved.b, moved.c)
    assert cells[2][0] == "(1,1,1), (3,1,1), (1,2,2)"
    assert cells[2][1:4] == [
        r.format(4, trim=True)["normal"],
        r.format(4, trim=True)["magnitude"],
        r.format(4, trim=True)["area"],
    ]
    assert cells[2][1] == "(0, -2, 2)"


def test_escaped_markdown_has_five_columns_everywhere():
    for line in guide.comparison_table_markdown(escape_pipes=True).splitlines():
        assert line.replace("\\|", "").count("|") == 6


def test_parse_markdown_table_reads_escaped_pipes():
    text = guide.comparison_table_markdown(escape_pipes=True)
    assert guide.parse_markdown_table(text) == guide.comparison_table_cells()


def test_precision_changes_the_rounding():
    cells = guide.comparison_table_cells(precision=2)
    assert cells[3][2:4] == ["1.41", "0.71"]


def test_worked_example_matches_the_guide():
    w = guide.worked_example()
    ex = guide.WORKED_EXAMPLE
    for key in ("u", "v", "normal", "magnitude", "area", "unit_normal", "reversed_normal"):
        assert w[key] == getattr(ex, key), key
    text = guide.worked_example_markdown()
    assert "N = U × V = (0, 0, 1)" in text
    assert "(0, 0, -1)" in text


def guide_text() -> str:
    """The seed file when present, else the stored excerpts of it (kept in sync below)."""
    return (SEED if SEED.is_file() else EXCERPTS).read_text(encoding="utf-8")


def test_stored_excerpts_are_in_the_seed():
    lines = EXCERPTS.read_text(encoding="utf-8").splitlines()
    assert len(lines) == 4
    if SEED.is_file():
        seed = SEED.read_text(encoding="utf-8").splitlines()
        assert all(line in seed for line in lines)


def test_worked_example_facts_are_in_the_guide():
    text = guide_text()
    assert "A = (0, 0, 0), B = (1, 0, 0), and C = (0, 1, 0)" in text
    assert "normal vector is (0, 0, 1)" in text
    assert "the result becomes (0, 0, -1)" in text


def test_precision_facts():
    f32, f64 = guide.PRECISION_FORMATS
    assert (f32.significand_bits, f64.significand_bits) == (24, 53)
    assert f32.decimal_digits_text == "about 7"
    assert f64.decimal_digits_text == "about 15 to 16"
    table = guide.precision_table_markdown()
    assert "| 32-bit float | 24 binary digits | About 7 decimal digits |" in table
    assert "| 64-bit double | 53 binary digits | About 15 to 16 decimal digits |" in table


def test_precision_facts_agree_with_the_guide():
    text = guide_text()
    for f in guide.PRECISION_FORMATS:
        digits = f.decimal_digits_text
        assert f"| {f.name} | {f.significand_bits} binary digits |" in text
        assert f"| {digits[:1].upper()}{digits[1:]} decimal digits |" in text


def test_five_mistakes():
    assert len(guide.MISTAKES) == 5
    assert all(name and text for name, text in guide.MISTAKES)


# --------------------------------------------------------------------------- the guide's words


GUIDE = ROOT / "docs" / "guide"
NOTEBOOKS = ROOT / "notebooks"


def notebook_text(name: str) -> str:
    import json

    nb = json.loads((NOTEBOOKS / name).read_text(encoding="utf-8"))
    return "\n".join("".join(c["source"]) for c in nb["cells"] if c["cell_type"] == "markdown")


def test_one_weighting_recommendation_everywhere():
    """The guide, notebooks 04 and 08 and the package default agree: angle weighting."""
    import inspect

    from trinormal import mesh

    assert inspect.signature(mesh.vertex_normals).parameters["weighting"].default == "angle"
    practice = " ".join((GUIDE / "practice.md").read_text(encoding="utf-8").split())
    assert "trinormal recommends it and uses it by default" in practice
    assert "exactly the weight you want" not in practice
    for name in ("04_common_mistakes.ipynb", "08_vertex_normals.ipynb"):
        assert "recommends **angle weighting**" in notebook_text(name), name


def test_the_size_limits_the_precision_page_states():
    """Products of coordinates underflow at the sizes the guide names, and not before."""
    page = " ".join((GUIDE / "precision.md").read_text(encoding="utf-8").split())
    assert "$10^{-23}$" in page and "$10^{-200}$" in page

    def n_float(size: float, arithmetic: str) -> tuple[float, ...]:
        t = ((0, 0, 0), (size, 0, 0), (0, size, 0))
        return triangle_normal(*t, arithmetic=arithmetic, tol=0).normal

    assert n_float(1e-23, "float32") == (0.0, 0.0, 0.0)
    assert n_float(1e-200, "float64") == (0.0, 0.0, 0.0)
    assert n_float(1e-20, "float32")[2] > 0  # subnormal, but not zero
    assert n_float(1e-150, "float64")[2] > 0
    assert triangle_normal((0, 0, 0), (1e-200, 0, 0), (0, 1e-200, 0)).unit_normal == (0.0, 0.0, 1.0)


def test_ray_front_face_rule_as_the_guide_states_it():
    """n · d < 0: the ray travels against the normal and meets the front."""
    page = " ".join((GUIDE / "practice.md").read_text(encoding="utf-8").split())
    assert "(negative: the ray travels against the normal)" in page
    n = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0)).normal  # faces +z
    down = (0, 0, -1)  # a ray from above
    assert sum(a * b for a, b in zip(n, down, strict=True)) < 0


def test_coincident_points_have_their_own_message():
    twin = triangle_normal((0, 0, 0), (1, 2, 3), (1, 2, 3)).format()["status"]
    line = triangle_normal((0, 0, 0), (1, 1, 1), (2, 2, 2)).format()["status"]
    assert "coincide" in twin and "collinear" not in twin and twin != line
    assert "B equals C" in (GUIDE / "degenerate.md").read_text(encoding="utf-8")
