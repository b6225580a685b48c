"""Exercises of notebook 11, your own mesh.

Both are judged by running the package on the answer: a face number is right when
[`trinormal.mesh.check`][trinormal.mesh.check] lists it among the faces to flip, and a set
of faces is right when the report of the repaired tetrahedron finds nothing wrong. So every
right answer counts (any of the 53 faces, any order of the faces, any starting corner).
"""

from __future__ import annotations

from fractions import Fraction
from typing import Any

from trinormal.exercises import AnswerError, Exercise, read_number, read_points
from trinormal.exercises.reading import FACES

#: The tetrahedron of exercise 11-repair-tetra: its corners ...
TETRA_VERTICES: tuple[tuple[int, int, int], ...] = ((0, 0, 0), (1, 0, 0), (0, 1, 0), (0, 0, 1))
#: ... and its faces as given, one of them wound the wrong way.
TETRA_FACES: tuple[tuple[int, int, int], ...] = ((0, 2, 1), (0, 1, 3), (0, 3, 2), (1, 3, 2))


def _ball() -> tuple[int, frozenset[int]]:
    """Return the damaged ball's face count and the faces its report says to flip (read anew)."""
    from trinormal import mesh

    m = mesh.read_mesh(mesh.sample_path())
    return len(m.faces), frozenset(int(i) for i in mesh.check(m.vertices, m.faces).faces_to_flip)


def _whole(x: Any) -> int:
    """Read a whole number, or raise AnswerError."""
    value = read_number(x)
    if isinstance(value, float) and value.is_integer():  # 70.0 is face 70
        value = Fraction(value)
    if not isinstance(value, Fraction) or value.denominator != 1:
        raise AnswerError("a face or vertex number is a whole number such as 17")
    return int(value)


def _check_flipped_face(answer: Any) -> tuple[bool, str]:
    try:
        face = _whole(answer)
    except AnswerError as error:
        return False, f"Your answer could not be read: {error}."
    except Exception:  # an object that breaks when read
        return False, "Your answer could not be read: give one whole number, such as 17."
    n_faces, to_flip = _ball()  # read once the answer is a number: an unread one needs no ball
    if not 0 <= face < n_faces:
        return False, (
            f"The ball has faces 0 to {n_faces - 1}; there is no face {face}. Click a face "
            "with an outline in the view to see its number."
        )
    if face in to_flip:
        return True, ""
    return False, (
        f"Face {face} is wound like its neighbours: its normal points out of the ball. The "
        "faces to flip are the ones the view outlines (a face you see blue through the hole "
        "is the inside of a face wound correctly); report.faces_to_flip lists them."
    )


def _read_faces(answer: Any) -> list[tuple[int, int, int]]:
    """Read four faces of three vertex numbers each (the shared reader), or raise AnswerError."""
    faces = []
    for k, row in enumerate(read_points(answer, 4, items=FACES)):
        try:
            corners = [_whole(x) for x in row]
        except AnswerError as error:
            raise AnswerError(f"face {k + 1}: {error}") from None
        faces.append((corners[0], corners[1], corners[2]))
    return faces


_FACES_WANTED = "give a list of 4 faces, each a list of 3 vertex numbers"


def _check_repair_tetra(answer: Any) -> tuple[bool, str]:
    from trinormal import mesh

    try:
        faces = _read_faces(answer)
    except AnswerError as error:
        return False, f"Your answer could not be read: {error}."
    except Exception:  # an object that breaks when read: say what is wanted
        return False, f"Your answer could not be read: {_FACES_WANTED}."
    given = sorted(sorted(f) for f in TETRA_FACES)
    if sorted(sorted(f) for f in faces) != given:
        return False, (
            "Keep the same four triangles: each face must use the same three corners as one of "
            "the faces given. Only the order of the corners in one face changes."
        )
    if len({tuple(sorted(f)) for f in faces}) != 4:
        return False, "Two of your faces use the same three corners: list each face once."
    report = mesh.check(TETRA_VERTICES, faces)
    if report.ok:
        return True, ""
    if sorted(faces) == sorted(TETRA_FACES):
        return False, (
            "These are the faces as given: one of them is still wound against its neighbours. "
            "Swap two corners of that one face."
        )
    if not report.consistent_winding:
        n = len(report.faces_to_flip)
        return False, (
            "Your faces are not wound consistently: across every shared edge the two faces "
            "must walk the edge in opposite directions (mesh.check says to turn "
            f"{'1 face' if n == 1 else f'{n} faces'} over)."
        )
    return False, (
        "Every face is wound the same way now, but the normals point into the tetrahedron "
        "(its signed volume is negative): turn every face over."
    )


EXERCISES = (
    Exercise(
        "11-flipped-face",
        "Give the number of one face of the damaged ball that is wound against its neighbours.",
        checker=_check_flipped_face,
        example=lambda: min(_ball()[1]),
        hint="Click a face the view outlines, or look at the report's faces_to_flip.",
    ),
    Exercise(
        "11-repair-tetra",
        "TETRA_FACES has one face wound the wrong way. Write the four faces with that face "
        "turned over, so that mesh.check(TETRA_VERTICES, faces).ok is True.",
        checker=_check_repair_tetra,
        example=lambda: (TETRA_FACES[0], TETRA_FACES[1], TETRA_FACES[2], (1, 2, 3)),
        hint=(
            "Find the face whose normal points inward, and swap two of its corners: compare "
            "each face's normal with the way out, from the tetrahedron's centre to the face's "
            "centre. Or read mesh.check(TETRA_VERTICES, TETRA_FACES).faces_to_flip."
        ),
    ),
)
