"""Reading answers: any object a student may hand to ``check``, read into exact values.

One reader serves every exercise, so an answer is read the same way wherever it
is typed. The rules:

* **Numbers.** ``int``, ``Fraction``, ``Decimal``, numpy integers, sympy
  rationals and decimal or fraction text (``"0.25"``, ``"1/3"``, ``"−6"`` with
  the Unicode minus) are *exact*: they are read as a ``Fraction``.
  A **decimal comma** is read in text that is one number with one comma
  (``"0,25"``); ``"1,500"`` (one to three digits, not starting with 0, then
  three) could be 1.5 or 1500 and gets a message asking for a point. Inside a
  calculation a comma separates a function's arguments (``"log(2, 10)"``),
  never decimals. ``float``,
  numpy floats and sympy ``Float`` are *floats*: read as a Python ``float``
  (exactly the binary value given). An irrational value (``sympy.sqrt(3) / 2``,
  ``"sqrt(3)/2"``, ``"√3/2"``, ``"2√2"``, ``"53*log(2)/log(10)"``) is read as
  the float nearest to it. A prompt's formula may be typed with its numbers:
  ``"|−6|"`` is an absolute value, ``"|(1, 2, 2)|"`` a vector's length,
  ``"log10(2)"``, ``"max(0, 0.8)"`` and ``"degrees(atan2(1, 2))"`` are what
  they say, and ``math.``, ``np.`` or ``sympy.`` before a function is dropped.
  The limits of the package's own reader
  ([`trinormal.validation.check_coordinate`][trinormal.validation.check_coordinate])
  apply: at most 400 digits.
* **One value in a box** counts as that value: a 0-d numpy array (what
  ``np.dot`` or ``np.cross`` of 2-D vectors return), an array, matrix, list or
  tuple of one element, a 1 × 1 sympy matrix or array.
* **Vectors**: tuples, lists, generators, numpy arrays or matrices of shape
  ``(3,)``, ``(3, 1)`` or ``(1, 3)``, sympy matrices and arrays of those
  shapes, and text as printed (``"(0, 0, 1)"``, ``"[1/√5, 2/√5, 0]"``), also
  with a factor (``"(0, -1, 1)/sqrt(2)"``, ``"[0,-1,1]/√2"``,
  ``"2*(1, 0, 0)"``). In text a comma separates components, unless ``;``
  does: then a comma is a decimal comma (``"(0,5; 1; 0)"``); components
  separated by spaces may have decimal commas too (``"0,5 1 0"``).
* **True or False**: ``True``/``False``, numpy booleans (also a one-element
  boolean array) and sympy's, and the words as text.
* **Words**: a word answer with listed choices (``"front"`` or ``"back"``) may
  be a sentence naming exactly one of them (``"It is the front."``); a
  sentence naming two, or with a negation, is not read.
* **Points**: a sequence of points, an ``(n, 3)`` array or matrix, a dict
  ``{"A": ..., "B": ..., "C": ...}``, or text such as ``"(0,0,1), (1,0,1), (0,1,1)"``.
* **Angles in degrees** may carry the degree sign (``"19.5°"``) where the
  exercise asks for degrees, and only there.

Everything else raises `AnswerError` with a message that says what was
expected; no other exception leaves these readers.

The modules, each named for what it reads:

* `errors` — `AnswerError` and the words of its messages (`describe`);
* `text` — typed math (``√3/2``, ``2√2``, ``x²``) read safely with sympy;
* `numbers` — `read_number`, one number;
* `vectors` — `read_vector` and `read_points` (points, or faces as `FACES`);
* `words` — `read_bool` and `read_word`;
* `expressions` — `read_expression`, one symbolic expression.

Examples
--------
>>> read_number("−7/4"), read_number(2.5), read_number("√2") ** 2 > 1.99
(Fraction(-7, 4), 2.5, True)
>>> read_vector("(1/4, 0, −2)")
[Fraction(1, 4), Fraction(0, 1), Fraction(-2, 1)]
>>> read_number(None)
Traceback (most recent call last):
...
trinormal.exercises.reading.errors.AnswerError: None is not a number (did a function print its result instead of returning it?)
"""  # noqa: E501

from trinormal.exercises.reading.errors import AnswerError, describe
from trinormal.exercises.reading.expressions import VectorGiven, read_expression
from trinormal.exercises.reading.numbers import Number, is_exact, read_number
from trinormal.exercises.reading.text import sympify_text as sympify_text
from trinormal.exercises.reading.vectors import FACES, POINTS, Items, read_points, read_vector
from trinormal.exercises.reading.words import read_bool, read_choice, read_word

__all__ = [
    "FACES",
    "POINTS",
    "AnswerError",
    "Items",
    "Number",
    "VectorGiven",
    "describe",
    "is_exact",
    "read_bool",
    "read_choice",
    "read_expression",
    "read_number",
    "read_points",
    "read_vector",
    "read_word",
]
