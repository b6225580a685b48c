"""Reference values for the tests, computed independently of trinormal with Fraction and Decimal."""

from __future__ import annotations

import importlib.util
import math
from decimal import Decimal, localcontext
from fractions import Fraction
from pathlib import Path
from types import ModuleType


def exact_normal(a, b, c, winding="ABC"):
    """N = (B − A) × (C − A) with Fractions: a reference independent of trinormal.core."""
    A, B, C = ([Fraction(x) for x in p] for p in (a, b, c))
    if winding == "ACB":
        B, C = C, B
    u = [B[i] - A[i] for i in range(3)]
    v = [C[i] - A[i] for i in range(3)]
    n = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
    return u, v, n


def sqrt_decimal(q: Fraction, digits: int = 80) -> Decimal:
    with localcontext() as ctx:
        ctx.prec = digits
        return (Decimal(q.numerator) / Decimal(q.denominator)).sqrt()


def ulps(x: float, ref: Decimal) -> float:
    """Distance from x to the reference value in units in the last place of the reference."""
    r = float(ref)
    if r == 0.0:
        return 0.0 if x == 0.0 else math.inf
    with localcontext() as ctx:
        ctx.prec = 80
        return float(abs(Decimal(x) - ref) / Decimal(math.ulp(r)))


DATA = Path(__file__).parent / "data"


def vector_generator(name: str) -> ModuleType:
    """Import a test-vector generator from tests/data (``make_calculator_vectors`` …) by name."""
    spec = importlib.util.spec_from_file_location(name, DATA / f"{name}.py")
    assert spec is not None and spec.loader is not None
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module
