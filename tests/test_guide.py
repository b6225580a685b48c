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


# --------------------------------------------------------------------------- when to normalise


def test_normalising_cases_agree_with_the_mesh_weightings():
    """Three recipes are mesh.vertex_normals' weightings (computed independently there)."""
    import numpy as np

    from trinormal import mesh

    cases = {c.recipe: c for c in guide.normalising_cases()}
    v, f = np.array(guide.SLIVER_VERTICES, dtype=float), np.array(guide.SLIVER_FACES)
    for recipe, weighting in (
        ("unit normals summed", "uniform"),
        ("raw normals summed", "area"),
        ("unit normals × corner angles", "angle"),
    ):
        want = mesh.vertex_normals(v, f, weighting)[0]
        assert np.allclose(cases[recipe].normal, want, rtol=0, atol=1e-12), recipe
    assert [c.mistake for c in guide.normalising_cases()] == [True, False, False, True]


def test_raw_normals_times_angles_is_not_angle_weighting():
    """The slip the old notebook 04 'fix' led to: raw N times the angle, by numpy."""
    import numpy as np

    v = np.array(guide.SLIVER_VERTICES, dtype=float)
    total = np.zeros(3)
    for face in guide.SLIVER_FACES:
        p, q, r = v[list(face)]
        n = np.cross(q - p, r - p)
        u, w = q - p, r - p
        total += n * np.arccos(u @ w / np.linalg.norm(u) / np.linalg.norm(w))
    total /= np.linalg.norm(total)
    got = {c.recipe: c.normal for c in guide.normalising_cases()}["raw normals × corner angles"]
    assert np.allclose(got, total, rtol=0, atol=1e-12)
    angle = {c.recipe: c.normal for c in guide.normalising_cases()}["unit normals × corner angles"]
    assert np.degrees(np.arccos(np.clip(np.dot(got, angle), -1, 1))) > 5  # visibly different


def test_the_mistake_text_and_practice_page_carry_the_numbers():
    text = dict(guide.MISTAKES)["normalizing too early"]
    from trinormal import format_vector

    for case in guide.normalising_cases():
        assert format_vector(case.normal, 4, trim=True) in text
    practice = (GUIDE / "practice.md").read_text(encoding="utf-8")
    assert "{{ trinormal:normalising_table }}" in practice
    assert "{{ trinormal:mistakes }}" in practice


def test_the_notebooks_tell_one_story_about_normalising():
    """No notebook says to keep raw normals for angle weighting (the contradiction of issue 18)."""
    for name in ("04_common_mistakes.ipynb", "08_vertex_normals.ipynb", "09_shading.ipynb"):
        text = " ".join(notebook_text(name).split())
        assert "keep raw normals (or the corner angles) until the sum is done" not in text, name
    assert "## Mistake 4: normalizing too early" in notebook_text("04_common_mistakes.ipynb")


def test_reflect_keeps_length_flips_the_normal_part_and_is_an_involution():
    import random
    from fractions import Fraction

    rng = random.Random(18)
    for _ in range(200):
        d = [Fraction(rng.randint(-50, 50), rng.randint(1, 9)) for _ in range(3)]
        n = [Fraction(rng.randint(-50, 50), rng.randint(1, 9)) for _ in range(3)]
        if not any(n):
            continue
        r = guide.reflect(d, n)
        assert sum(x * x for x in r) == sum(x * x for x in d)
        assert sum(a * b for a, b in zip(r, n, strict=True)) == -sum(
            a * b for a, b in zip(d, n, strict=True)
        )
        assert list(guide.reflect(r, n)) == d
        scaled = [3 * x for x in n]
        assert guide.reflect(d, scaled) == r  # only the direction of N matters


def test_reflect_matches_the_unit_normal_formula_and_refuses_a_zero_normal():
    import math

    import pytest

    n = triangle_normal((1, 1, 1), (2, 1, 1), (1, 2, 2))
    d = (0.3, -1.0, 0.2)
    u = n.unit_normal
    dot = sum(a * b for a, b in zip(d, u, strict=True))
    want = [a - 2 * dot * b for a, b in zip(d, u, strict=True)]
    got = [float(x) for x in guide.reflect(d, n.exact.normal)]
    assert all(math.isclose(a, b, rel_tol=0, abs_tol=1e-15) for a, b in zip(got, want, strict=True))
    with pytest.raises(ValueError, match="degenerate"):
        guide.reflect(d, (0, 0, 0))


# --------------------------------------------------------------------------- pages that stay current


def test_home_page_and_readme_describe_the_3d_explorer_as_it_is():
    """No stale claims (nine sliders above a picture, a kernel needed on the site); a phone-sized
    screenshot of the live view with alt text."""
    import re
    import struct

    home = " ".join((ROOT / "docs" / "index.md").read_text(encoding="utf-8").split())
    readme = " ".join((ROOT / "README.md").read_text(encoding="utf-8").split())
    notebooks = " ".join((ROOT / "docs" / "notebooks.md").read_text(encoding="utf-8").split())
    for text in (home, readme, notebooks):
        assert "nine sliders" not in text
        assert "sliders need a running Python kernel" not in text
        assert "explorer's sliders, need a running Python kernel" not in text
    for text in (home, readme):
        assert "3D" in text and "no kernel" in text and "Notebook 7" in text
        assert "calculator" in text.lower() and "05" in text
    image = ROOT / "docs" / "assets" / "images" / "explorer-3d.png"
    width, height = struct.unpack(">II", image.read_bytes()[16:24])
    assert 600 <= width <= 900 and height > width  # drawn at 2x for a phone's width
    assert re.search(r"!\[The live 3D explorer[^\]]{80,}\]\(assets/images/explorer-3d\.png\)", home)
    assert re.search(
        r'<img src="docs/assets/images/explorer-3d\.png"[^>]* alt="The live 3D', readme
    )
