"""Each student's own numbers: a bank of variants of the notebooks' exercises.

An exercise with a variant is built by its notebook module's factory (for example
``nb01.exercises_for(triangle)``) from numbers drawn here, so a variant has the same
checker, hints and slips as the notebook's own exercise. Exercises that share their
numbers form a *group*: the three exercises of notebook 01 are about one triangle.

Each group has a template: how to draw candidate numbers (small whole numbers and
halves), when the answers are clean (a rational area, no two of the listed mistakes
equal to the answer) and the factory. Variant ``i`` of a group is the ``i``-th clean,
distinct candidate drawn by a generator seeded with the group's name, so the bank is
the same on every machine and nothing is kept between calls.

A student's variant is chosen by a hash of their name (and a seed):
`variant_index`. A worksheet gives a whole roster distinct variants with `assign`,
which starts from the same hash and moves a student on to the next free variant when
a classmate already has theirs; it prints each student's variants as a short code
(`student_code`) for ``exercises.student(name, code)``, so the notebook gives the
student the worksheet's numbers.

>>> variant_exercise("01-normal", 0).prompt
'Compute N = (B − A) × (C − A) for A = (1, 2, 2), B = (1, 3/2, 0), C = (1, 3, 1).'
>>> assign(["Ana Lima", "Ben Okafor"], seed=1)["Ana Lima"]["05-scale-area"]
44
"""

from __future__ import annotations

import hashlib
import math
import random
from collections.abc import Callable, Iterable, Sequence
from dataclasses import dataclass
from fractions import Fraction
from typing import Any

from trinormal.exercises import Exercise, nb01, nb02, nb04, nb05

__all__ = [
    "BANK_SIZE",
    "TEMPLATES",
    "Template",
    "assign",
    "group_of",
    "read_code",
    "student_code",
    "variant_exercise",
    "variant_index",
    "variant_names",
    "variant_numbers",
]

#: How many variants each group has.
BANK_SIZE = 60
#: The coordinates a variant's triangle is drawn from: small whole numbers and two halves.
COORDINATES: tuple[Fraction, ...] = tuple(
    Fraction(x) for x in ("-2", "-1", "0", "0", "1", "1", "2", "2", "3", "1/2", "3/2")
)
#: The whole numbers edges and 2D points are drawn from.
WHOLE: tuple[Fraction, ...] = tuple(Fraction(x) for x in range(-3, 5))

Point = tuple[Fraction, ...]


def _sub(p: Sequence[Fraction], q: Sequence[Fraction]) -> Point:
    return tuple(a - b for a, b in zip(p, q, strict=True))


def _dot(p: Sequence[Fraction], q: Sequence[Fraction]) -> Fraction:
    return sum((a * b for a, b in zip(p, q, strict=True)), Fraction(0))


def _cross(u: Sequence[Fraction], v: Sequence[Fraction]) -> Point:
    return (u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0])


def _normal(abc: Sequence[Point]) -> Point:
    a, b, c = abc
    return _cross(_sub(b, a), _sub(c, a))


def _point(rng: random.Random, pool: Sequence[Fraction], size: int = 3) -> Point:
    return tuple(rng.choices(pool, k=size))


def _triangle(rng: random.Random, pool: Sequence[Fraction] = COORDINATES) -> tuple[Point, ...]:
    xs = rng.choices(pool, k=9)
    return (tuple(xs[0:3]), tuple(xs[3:6]), tuple(xs[6:9]))


def _clean_01(abc: Any) -> bool:
    """Keep a triangle with a rational area and |N| at least 2 (no listed mistake is right)."""
    n = _normal(abc)
    n2 = 16 * _dot(n, n)  # |4 N|², a whole number: the coordinates are halves
    return n2 >= 4 * 16 and math.isqrt(int(n2)) ** 2 == n2


def _clean_lagrange(uv: Any) -> bool:
    u, v = uv
    return abs(_dot(u, v)) >= 2 and _dot(_cross(u, v), _cross(u, v)) > 1


def _clean_dot(abc: Any) -> bool:
    a, b, c = abc
    return _dot(_sub(b, a), _sub(c, a)) not in (0, _normal(abc)[2])


def _clean_flat(pqr: Any) -> bool:
    p, q, r = ((*x, Fraction(0)) for x in pqr)
    return abs(_normal((p, q, r))[2]) >= 3


def _clean_scale(abk: Any) -> bool:
    triangle: tuple[Point, ...] = abk[0]
    fits = all(abs(abk[1] * x) <= nb05.EXPLORER_RANGE for p in triangle for x in p)
    return fits and any(_normal(triangle))


def _clean_line(ab: Any) -> bool:
    return bool(ab[0] != ab[1])


@dataclass(frozen=True)
class Template:
    """How the variants of one group of exercises are made.

    Attributes
    ----------
    names : tuple of str
        The exercises that share the numbers; the first names the group.
    draw : callable
        ``draw(rng)`` → one candidate's numbers.
    clean : callable
        ``clean(numbers)`` → True when the answers are clean and no listed mistake is right.
    build : callable
        ``build(numbers)`` → the exercises, in the order of ``names``.
    """

    names: tuple[str, ...]
    draw: Callable[[random.Random], Any]
    clean: Callable[[Any], bool]
    build: Callable[[Any], tuple[Exercise, ...]]

    @property
    def group(self) -> str:
        """The group's name: its first exercise."""
        return self.names[0]

    def numbers(self, count: int = BANK_SIZE) -> list[Any]:
        """Draw the first ``count`` variants' numbers, variant 0 first (again on each call)."""
        rng = random.Random(f"trinormal-variants-{self.group}")
        found: list[Any] = []
        seen: set[Any] = set()
        while len(found) < count:
            candidate = self.draw(rng)
            if candidate not in seen and self.clean(candidate):
                seen.add(candidate)
                found.append(candidate)
        return found


TEMPLATES: tuple[Template, ...] = (
    Template(("01-normal", "01-area", "01-reversed"), _triangle, _clean_01, nb01.exercises_for),
    Template(
        ("02-lagrange",),
        lambda rng: (_point(rng, WHOLE), _point(rng, WHOLE)),
        _clean_lagrange,
        lambda uv: (nb02.lagrange_exercise(*uv),),
    ),
    Template(
        ("04-dot-value",),
        lambda rng: _triangle(rng, WHOLE),
        _clean_dot,
        lambda abc: (nb04.dot_value_exercise(abc),),
    ),
    Template(
        ("04-2d-nz",),
        lambda rng: tuple(_point(rng, WHOLE, 2) for _ in range(3)),
        _clean_flat,
        lambda pqr: (nb04.flat_nz_exercise(pqr),),
    ),
    Template(
        ("05-collinear",),
        lambda rng: (_point(rng, WHOLE), _point(rng, WHOLE)),
        _clean_line,
        lambda ab: (nb05.collinear_exercise(ab),),
    ),
    Template(
        ("05-scale-area",),
        lambda rng: (_triangle(rng, WHOLE), rng.randint(2, 5)),
        _clean_scale,
        lambda abk: (nb05.scale_area_exercise(*abk),),
    ),
)


def variant_names() -> list[str]:
    """Every exercise that has variants, in the notebooks' order.

    Examples
    --------
    >>> variant_names()[:3]
    ['01-normal', '01-area', '01-reversed']
    """
    return [name for t in TEMPLATES for name in t.names]


def group_of(name: str) -> Template | None:
    """Return the template of the exercise ``name``, None when it has no variants.

    Examples
    --------
    >>> group_of("01-area").group, group_of("06-float64-bits")
    ('01-normal', None)
    """
    return next((t for t in TEMPLATES if name in t.names), None)


def _template(name: str) -> Template:
    found = group_of(name)
    if found is None:
        raise KeyError(f"exercise {name!r} has no variants (variant_names() lists those that do)")
    return found


def variant_numbers(name: str, index: int) -> Any:
    """Return the numbers of variant ``index`` of the exercise ``name``'s group."""
    if not 0 <= index < BANK_SIZE:
        raise IndexError(f"variant {index} of {name!r}: there are {BANK_SIZE}, from 0")
    return _template(name).numbers(index + 1)[index]


def variant_exercise(name: str, index: int) -> Exercise:
    """Return variant ``index`` (0 to ``BANK_SIZE - 1``) of the exercise ``name``.

    Examples
    --------
    >>> variant_exercise("05-scale-area", 3).prompt[-44:]
    'by 2. By what number is the area multiplied?'
    """
    template = _template(name)
    built = template.build(variant_numbers(name, index))
    return built[template.names.index(name)]


def _key(name: str) -> str:
    return " ".join(name.split()).casefold()


def variant_index(name: str, student: str, seed: int = 0) -> int:
    """Pick a student's variant of an exercise: a hash of the group, the name and the seed.

    Names differing only in case or spacing pick the same variant.

    Examples
    --------
    >>> variant_index("01-area", "Ana Lima") == variant_index("01-normal", " ana  lima")
    True
    """
    text = f"{seed}\0{_template(name).group}\0{_key(student)}"
    return int(hashlib.sha256(text.encode()).hexdigest(), 16) % BANK_SIZE


def assign(roster: Iterable[str], seed: int = 0) -> dict[str, dict[str, int]]:
    """Give every student of a roster a variant of each group, distinct while the bank lasts.

    Students are served in roster order: each gets `variant_index`, or the next variant
    no classmate has yet; once all ``BANK_SIZE`` are taken, they are handed out again.

    Returns
    -------
    dict
        ``{student: {group: variant}}``, a group being named by its first exercise.

    Raises
    ------
    ValueError
        When two names on the roster are the same (ignoring case and spacing).
    """
    students = list(roster)
    keys = [_key(s) for s in students]
    twice = next((s for s, k in zip(students, keys, strict=True) if keys.count(k) > 1), None)
    if twice is not None:
        raise ValueError(f"{twice!r} is on the roster twice: give each student a distinct name")
    out: dict[str, dict[str, int]] = {s: {} for s in students}
    for template in TEMPLATES:
        used: set[int] = set()
        for student in students:
            if len(used) == BANK_SIZE:
                used.clear()
            index = variant_index(template.group, student, seed)
            while index in used:
                index = (index + 1) % BANK_SIZE
            used.add(index)
            out[student][template.group] = index
    return out


def student_code(variants: dict[str, int]) -> str:
    """Write a student's variants (``{group: variant}``) as the code ``student(name, code)`` takes.

    Examples
    --------
    >>> code = student_code(assign(["Ana Lima"], seed=1)["Ana Lima"])
    >>> read_code(code) == assign(["Ana Lima"], seed=1)["Ana Lima"]
    True
    """
    return ".".join(str(variants[t.group]) for t in TEMPLATES)


def read_code(code: str) -> dict[str, int]:
    """Read a code written by `student_code`.

    Raises
    ------
    ValueError
        When the code is not one number per group, each below ``BANK_SIZE``.
    """
    parts = str(code).strip().split(".")
    if len(parts) != len(TEMPLATES) or not all(p.isdigit() and int(p) < BANK_SIZE for p in parts):
        raise ValueError(
            f"the code {code!r} is not one from a worksheet: it should be {len(TEMPLATES)} "
            f"whole numbers below {BANK_SIZE} joined by dots"
        )
    return {t.group: int(p) for t, p in zip(TEMPLATES, parts, strict=True)}
