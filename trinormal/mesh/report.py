"""What is wrong with a mesh, in numbers and in plain words: `check`.

The report answers a student's first questions about a model that renders
black in places or has faces missing: are some faces flat (no normal), are
some there twice, are there holes, do pieces meet along fins or at single
points, is every piece wound one way, and does every closed piece face out?
"""

from __future__ import annotations

import textwrap
from dataclasses import asdict, dataclass, field
from functools import partial
from typing import Any

import numpy as np
import numpy.typing as npt

from trinormal.mesh._arrays import IntArray, _check_faces, _check_tol, _check_vertices
from trinormal.mesh.normals import degenerate_faces
from trinormal.mesh.printing import Measures, PrintReport, _fill, _holes, measure, print_report
from trinormal.mesh.repair import _Winding, _winding
from trinormal.mesh.topology import (
    _boundary_edges,
    _distinct_corners,
    _duplicates,
    _non_manifold_edges,
    _non_manifold_vertices,
)
from trinormal.mesh.welding import round_distance
from trinormal.mesh.welding import weld as weld_faces
from trinormal.tolerances import DEFAULT_TOL

__all__ = ["NOUNS", "SUMMARY", "ComponentReport", "MeshReport", "check"]


@dataclass(frozen=True)
class ComponentReport:
    """One connected piece of a mesh.

    Attributes
    ----------
    faces : int
        How many faces the piece has.
    closed : bool
        Every edge of the piece is shared by exactly two of its faces (no hole,
        no fin): the piece has an inside.
    consistent : bool
        Every edge shared by two faces is walked once each way.
    orientable : bool
        The piece can be wound consistently at all (a Möbius strip cannot).
    outward : bool or None
        For a consistently wound piece judged by a volume (``judged_by``): True
        if its normals point away from its material (out of a solid, into a
        cavity), False if they point into it; None when the question has no
        answer (an inconsistent piece, a sheet, no volume to speak of).
    volume : float or None
        The enclosed volume as the faces are wound now (negative: the normals
        point in, right for a cavity), for a closed, consistently wound piece;
        otherwise None.
    faces_to_flip : int
        How many of its faces `trinormal.mesh.fix_winding` turns over.
    cavity : bool
        A closed piece inside an odd number of other closed pieces: the hollow
        of a wall with thickness, whose normals should point into it.
    judged_by : str or None
        What tells this piece's outside from its inside: ``"volume"`` (a closed
        piece, its enclosed volume), ``"volume_over_holes"`` (an open piece that
        mostly encloses a volume, closed over its holes: `trinormal.mesh.shells`),
        or None (a sheet or terrain, no volume, or no consistent winding).
    """

    faces: int
    closed: bool
    consistent: bool
    orientable: bool
    outward: bool | None
    volume: float | None
    faces_to_flip: int
    cavity: bool = False
    judged_by: str | None = None

    def to_dict(self) -> dict[str, Any]:
        """Return the fields as a JSON-ready dictionary."""
        return asdict(self)


@dataclass(frozen=True)
class MeshReport:
    """Everything `check` found; indices refer to the arrays it was given.

    Attributes
    ----------
    n_vertices, n_faces : int
        Sizes of the mesh.
    unused_vertices : ndarray of int
        Vertices no face uses.
    degenerate_faces : ndarray of int
        Faces with no normal: ``coincident_faces`` and ``collinear_faces`` together.
    coincident_faces : ndarray of int
        Faces with two corners at exactly the same point (or one vertex used twice).
    collinear_faces : ndarray of int
        The other degenerate faces: corners on one line, or so nearly that
        ``|N| <= tol · L²``, N the face's normal and L its longest side (see
        `trinormal.mesh.degenerate_faces`).
    duplicate_faces, reversed_duplicate_faces : ndarray of int
        Faces repeating an earlier face's three vertices, wound the same way
        or only the other way (see `trinormal.mesh.duplicate_faces`).
    boundary_edges : ndarray of int, shape (k, 2)
        Edges used by one face only, as that face walks them: rims of holes.
    non_manifold_edges : ndarray of int, shape (k, 2)
        Edges shared by three faces or more.
    non_manifold_vertices : ndarray of int
        Vertices where separate fans of faces touch at a single point.
    inconsistent_edges : ndarray of int, shape (k, 2)
        Edges shared by two faces that walk them the same way (one of the two
        is flipped), as ``(smaller, larger)`` vertex index.
    face_component : ndarray of int, shape (F,)
        The piece of each face (-1 for a face that uses one vertex twice).
    components : tuple of ComponentReport
        One entry per piece, in the order of their first faces.
    faces_to_flip : ndarray of int
        The faces `trinormal.mesh.fix_winding` turns over.
    measures : trinormal.mesh.printing.Measures
        The surface area and the bounding box; `MeshReport.printing` adds the holes,
        the volume and the verdict (the report for printing).
    weld_distance : float
        Boundary corners no farther apart than this along each axis were merged
        for the topology (corners at one position always are).
    merged_vertices : int
        How many vertices the topology replaced by another at exactly their position.
    welded_vertices : int
        How many others it replaced by a boundary corner within ``weld_distance``.
    near_miss_edges : int
        Boundary edges that would close if corners closer than
        ``near_miss_distance`` were merged too (0: none).
    near_miss_distance : float or None
        That distance: ``weld=`` it to merge them.
    holes : tuple of int
        The number of edges around each hole, largest first (the rims of
        ``boundary_edges`` joined end to end; `MeshReport.printing`).

    Examples
    --------
    >>> from trinormal.mesh import cube
    >>> v, f = cube()
    >>> r = check(v, f[:-1])  # one face missing: a hole
    >>> r.n_faces, len(r.boundary_edges), r.closed
    (11, 3, False)
    """

    n_vertices: int
    n_faces: int
    unused_vertices: IntArray
    degenerate_faces: IntArray
    coincident_faces: IntArray
    collinear_faces: IntArray
    duplicate_faces: IntArray
    reversed_duplicate_faces: IntArray
    boundary_edges: IntArray
    non_manifold_edges: IntArray
    non_manifold_vertices: IntArray
    inconsistent_edges: IntArray
    face_component: IntArray = field(repr=False)
    components: tuple[ComponentReport, ...]
    faces_to_flip: IntArray
    measures: Measures = field(repr=False)
    weld_distance: float = 0.0
    merged_vertices: int = 0
    welded_vertices: int = 0
    near_miss_edges: int = 0
    near_miss_distance: float | None = None
    holes: tuple[int, ...] = field(default=(), repr=False)

    @property
    def printing(self) -> PrintReport:
        """Holes, area, volume, size and verdict: `trinormal.mesh.printing.print_report`."""
        return print_report(self)

    @property
    def consistent_winding(self) -> bool:
        """Every piece is wound consistently."""
        return all(c.consistent for c in self.components)

    @property
    def closed(self) -> bool:
        """Every piece is closed (no boundary edge, no non-manifold edge)."""
        return all(c.closed for c in self.components) and bool(self.components)

    @property
    def outward(self) -> bool | None:
        """Whether every piece with an inside faces out, wound consistently; None if none has.

        The pieces with an inside are the closed ones and the open ones that mostly
        enclose a volume (``judged_by``); a cavity faces out when it faces into its hollow.
        """
        judged = [c for c in self.components if c.closed or c.judged_by is not None]
        if not judged:
            return None
        return all(c.outward is True for c in judged)

    @property
    def ok(self) -> bool:
        """Nothing to report: a clean, closed, consistently and outward wound mesh."""
        return (
            self.closed
            and self.consistent_winding
            and self.outward is True
            and not any(
                len(a)
                for a in (
                    self.degenerate_faces,
                    self.duplicate_faces,
                    self.reversed_duplicate_faces,
                    self.non_manifold_vertices,
                    self.unused_vertices,
                )
            )
        )

    def to_dict(self) -> dict[str, Any]:
        """Every count and list as JSON-ready values (ints, bools, lists)."""
        return {
            "n_vertices": self.n_vertices,
            "n_faces": self.n_faces,
            "n_components": len(self.components),
            "closed": self.closed,
            "consistent_winding": self.consistent_winding,
            "outward": self.outward,
            "ok": self.ok,
            "unused_vertices": self.unused_vertices.tolist(),
            "degenerate_faces": self.degenerate_faces.tolist(),
            "coincident_faces": self.coincident_faces.tolist(),
            "collinear_faces": self.collinear_faces.tolist(),
            "duplicate_faces": self.duplicate_faces.tolist(),
            "reversed_duplicate_faces": self.reversed_duplicate_faces.tolist(),
            "boundary_edges": self.boundary_edges.tolist(),
            "non_manifold_edges": self.non_manifold_edges.tolist(),
            "non_manifold_vertices": self.non_manifold_vertices.tolist(),
            "inconsistent_edges": self.inconsistent_edges.tolist(),
            "components": [c.to_dict() for c in self.components],
            "faces_to_flip": self.faces_to_flip.tolist(),
            "weld_distance": self.weld_distance,
            "merged_vertices": self.merged_vertices,
            "welded_vertices": self.welded_vertices,
            "near_miss": None
            if self.near_miss_distance is None
            else {"edges": self.near_miss_edges, "distance": self.near_miss_distance},
            **self.printing.to_dict(),
        }

    def summary(self, width: int = 88) -> str:
        """Say what the report found in plain sentences, one finding per paragraph.

        Parameters
        ----------
        width : int, default 88
            Lines are wrapped at this many characters (0: no wrapping).

        Returns
        -------
        str
            The findings, one paragraph each; a paragraph's wrapped lines are
            indented by two spaces.

        Examples
        --------
        >>> from trinormal.mesh import cube
        >>> v, f = cube()
        >>> print(check(v, f).summary())
        8 vertices, 12 triangles, 1 piece.
        No problems found: the surface is closed, every face is wound the same way round, and
          every normal points outward.
        Size: 2 × 2 × 2 (x, y, z) in the file's units, which slicers read as mm.
        Read as millimetres its largest side, 2, is under 10 mm: if the model is in inches,
          scale it by 25.4 (by 10 if it is in centimetres).
        Surface area 24; enclosed volume 8.
        Verdict: watertight, 1 piece, wound outward: ready for a slicer.
        """
        lines = _summary_lines(self) + self.printing.lines()
        if width > 0:
            lines = [textwrap.fill(line, width, subsequent_indent="  ") for line in lines]
        return "\n".join(lines)


#: Things the summary counts: the singular and the plural.
NOUNS: dict[str, tuple[str, str]] = {
    "vertex": ("vertex", "vertices"),
    "triangle": ("triangle", "triangles"),
    "piece": ("piece", "pieces"),
    "face": ("face", "faces"),
    "edge": ("edge", "edges"),
}

#: The summary's sentences: a template, or a (one, many) pair chosen by its count ``{n}``.
#: The site's "Check a mesh" page writes its summary from these same templates.
SUMMARY: dict[str, str | tuple[str, str]] = {
    "sizes": "{vertices}, {triangles}, {pieces}.",
    "ok": (
        "No problems found: the surface is closed, every face is wound the same way round, "
        "and every normal points outward."
    ),
    "degenerate": (
        "{n} degenerate face ({parts}): no area and no normal, so they cannot be lit or oriented.",
        "{n} degenerate faces ({parts}): no area and no normal, so they cannot be lit or oriented.",
    ),
    "coincident": "{n} with two corners at the same point",
    "collinear": "{n} with corners on one line",
    "duplicate": (
        "{n} face repeats another face exactly.",
        "{n} faces repeat another face exactly.",
    ),
    "reversed_duplicate": (
        "{n} face repeats another face wound the other way: the two normals cancel, and the "
        "pair is a sheet with no inside.",
        "{n} faces repeat another face wound the other way: the two normals cancel, and the "
        "pair is a sheet with no inside.",
    ),
    "unused": ("{n} vertex is not used by any face.", "{n} vertices are not used by any face."),
    "boundary": (
        "{n} edge belongs to one face only: the surface has holes (or is an open sheet), so it "
        "is not watertight. Through a hole you see the back of the faces behind it.",
        "{n} edges belong to one face only: the surface has holes (or is an open sheet), so it "
        "is not watertight. Through a hole you see the back of the faces behind it.",
    ),
    "non_manifold_edges": (
        "{n} edge is shared by three faces or more, like the spine of a book: no single "
        "surface does that.",
        "{n} edges are shared by three faces or more, like the spine of a book: no single "
        "surface does that.",
    ),
    "non_manifold_vertices": (
        "{n} vertex is a pinch point: the faces around it make two fans or more that meet "
        "only there, like two cones tip to tip.",
        "{n} vertices are pinch points: the faces around each make two fans or more that meet "
        "only there, like two cones tip to tip.",
    ),
    "piece": "Piece {i} ({faces})",
    "whole": "The mesh",
    "not_orientable": (
        "{name} cannot be wound consistently at all, like a Möbius strip: it has only one side."
    ),
    "inconsistent": (
        "{name} is wound inconsistently: some faces are turned the other way round from their "
        "neighbours, so their normals point the wrong way. Lighting makes such faces dark, and "
        "back-face culling makes them vanish."
    ),
    "inside_out": (
        "{name} is inside out: every normal points inward (the enclosed volume is negative)."
    ),
    "no_volume": "{name} is closed but encloses no volume, so it has no outside.",
    "flip": (
        "Fixing the winding turns {n} face over, so that every piece is wound consistently{end}",
        "Fixing the winding turns {n} faces over, so that every piece is wound consistently{end}",
    ),
    "flip_end_closed": " and outward.",
    "flip_end_open": ".",
    "welded": (
        "{n} corner less than {distance} from another corner is taken as that corner, so the "
        "faces there join.",
        "{n} corners less than {distance} from another corner are taken as that corner, so the "
        "faces there join.",
    ),
    "near_miss": (
        "{n} boundary edge would close if corners closer than {distance} were merged: probably "
        "an export that did not weld its vertices.",
        "{n} boundary edges would close if corners closer than {distance} were merged: probably "
        "an export that did not weld its vertices.",
    ),
    "cavity": (
        "{name} is a cavity inside another closed piece, and its normals point into the hollow, "
        "away from the material, as they should."
    ),
    "cavity_inside_out": (
        "{name} is a cavity inside another closed piece, but its normals point out of the "
        "hollow, into the material: it is inside out."
    ),
    "open_inside_out": (
        "{name} is open, but closed over its holes it encloses a volume, and every normal "
        "points inward: it is inside out."
    ),
    "open_encloses": (
        "{name} is open, but closed over its holes it encloses a volume, so its outside can be "
        "told: its normals point outward.",
        "{n} open pieces enclose a volume when closed over their holes, so their outside can "
        "be told: their normals point outward.",
    ),
    "open_sheet": (
        "{name} is open and encloses nothing, like a sheet or a terrain: only whether its faces "
        "agree can be judged, not which side is out.",
        "{n} open pieces enclose nothing, like sheets or terrains: only whether their faces "
        "agree can be judged, not which side is out.",
    ),
}


_say = partial(_fill, SUMMARY)


def _n(count: int, noun: str) -> str:
    one, many = NOUNS[noun]
    return f"{count} {one if count == 1 else many}"


def _summary_lines(r: MeshReport) -> list[str]:
    lines = [
        _say(
            "sizes",
            vertices=_n(r.n_vertices, "vertex"),
            triangles=_n(r.n_faces, "triangle"),
            pieces=_n(len(r.components), "piece"),
        )
    ]
    if r.welded_vertices:
        distance = round_distance(r.weld_distance, above=False)[1]
        lines.append(_say("welded", n=r.welded_vertices, distance=distance))
    if r.ok:
        lines.append(_say("ok"))
        return lines + _piece_lines(r)
    if len(r.degenerate_faces):
        kinds = (("coincident", r.coincident_faces), ("collinear", r.collinear_faces))
        parts = ", ".join(_say(key, n=len(found)) for key, found in kinds if len(found))
        lines.append(_say("degenerate", n=len(r.degenerate_faces), parts=parts))
    for key, found in (
        ("duplicate", r.duplicate_faces),
        ("reversed_duplicate", r.reversed_duplicate_faces),
        ("unused", r.unused_vertices),
        ("boundary", r.boundary_edges),
        ("non_manifold_edges", r.non_manifold_edges),
        ("non_manifold_vertices", r.non_manifold_vertices),
    ):
        if len(found):
            lines.append(_say(key, n=len(found)))
    if r.near_miss_distance is not None:
        distance = round_distance(r.near_miss_distance, above=False)[1]
        lines.append(_say("near_miss", n=r.near_miss_edges, distance=distance))
    lines += _piece_lines(r)
    n_flip = len(r.faces_to_flip)
    if n_flip:  # "and outward" when some piece has an inside
        end = _say("flip_end_open" if r.outward is None else "flip_end_closed")
        lines.append(_say("flip", n=n_flip, end=end))
    return lines


def _piece_lines(r: MeshReport) -> list[str]:
    """Say what can be said of each piece's winding, and why; right open pieces counted."""
    lines = []
    many = len(r.components) > 1
    sheets: list[str] = []
    enclosing: list[str] = []
    for i, c in enumerate(r.components):
        name = _say("piece", i=i + 1, faces=_n(c.faces, "face")) if many else _say("whole")
        if not c.orientable:
            lines.append(_say("not_orientable", name=name))
        elif not c.consistent:
            lines.append(_say("inconsistent", name=name))
        elif c.closed and c.cavity:
            lines.append(_say("cavity" if c.outward else "cavity_inside_out", name=name))
        elif c.closed and c.outward is False:
            lines.append(_say("inside_out", name=name))
        elif c.closed and c.outward is None:
            lines.append(_say("no_volume", name=name))
        elif not c.closed and c.outward is False:
            lines.append(_say("open_inside_out", name=name))
        elif not c.closed and c.outward is True:
            enclosing.append(name)
        elif not c.closed:
            sheets.append(name)
    for key, found in (("open_encloses", enclosing), ("open_sheet", sheets)):
        if found:
            lines.append(_say(key, n=len(found), name=found[0]))
    return lines


def check(
    vertices: npt.ArrayLike,
    faces: npt.ArrayLike,
    tol: float = DEFAULT_TOL,
    weld: float | bool = False,
) -> MeshReport:
    """Find everything wrong with a mesh: degenerate, duplicate and flipped faces, holes, fins.

    Parameters
    ----------
    vertices, faces : array_like
        The mesh, shapes (V, 3) and (F, 3), as `trinormal.mesh.face_normals`
        takes them; the report's indices refer to these rows.
    tol : float, default ``trinormal.tolerances.DEFAULT_TOL``
        Degeneracy threshold: a face is degenerate when ``|N| <= tol · L²``,
        N its normal and L its longest side, whatever the mesh's scale (see
        `trinormal.mesh.degenerate_faces`).
    weld : float or bool, default False
        The topology (edges, holes, pieces, winding) joins corners at exactly one
        position, and boundary corners closer than ``WELD_AUTO`` times the model's
        size (`trinormal.mesh.welding`). A number merges boundary corners up to that
        distance apart along each axis; True, up to the distance of the near miss the
        report would suggest; 0, only corners at exactly one position.

    Returns
    -------
    MeshReport
        Counts, face and edge lists, and `MeshReport.summary` in words.

    Raises
    ------
    ValueError
        Bad arrays, with the message naming the first bad row.

    Examples
    --------
    A cube with its top face turned over and its bottom missing:

    >>> from trinormal.mesh import cube
    >>> v, f = cube()
    >>> f = f.copy()
    >>> f[10:] = f[10:, [0, 2, 1]]
    >>> r = check(v, f[2:])
    >>> len(r.boundary_edges), r.faces_to_flip
    (4, array([8, 9]))
    >>> print(r.summary())
    8 vertices, 10 triangles, 1 piece.
    4 edges belong to one face only: the surface has holes (or is an open sheet), so it is
      not watertight. Through a hole you see the back of the faces behind it.
    The mesh is wound inconsistently: some faces are turned the other way round from their
      neighbours, so their normals point the wrong way. Lighting makes such faces dark, and
      back-face culling makes them vanish.
    Fixing the winding turns 2 faces over, so that every piece is wound consistently and
      outward.
    1 hole: 4 edges around it.
    Size: 2 × 2 × 2 (x, y, z) in the file's units, which slicers read as mm.
    Read as millimetres its largest side, 2, is under 10 mm: if the model is in inches,
      scale it by 25.4 (by 10 if it is in centimetres).
    Surface area 20; no enclosed volume: only a closed, consistently wound piece has an
      inside to measure.
    Verdict: not watertight, 1 piece, wound inconsistently: not ready for a slicer (1 hole,
      2 faces to turn over).
    """
    t = _check_tol(tol)
    v, _ = _check_vertices(vertices)
    f = _check_faces(faces, v.shape[0])
    nv, nf = v.shape[0], f.shape[0]
    welded = weld_faces(v, f, weld)
    he = welded.half_edges

    deg = degenerate_faces(v, f, t)
    # two corners at exactly one point: one vertex, once vertices at one position are one
    coincident = ~_distinct_corners(f if welded.exact is None else welded.exact[f])
    deg |= coincident
    collinear = deg & ~coincident

    used = np.zeros(nv, dtype=bool)
    used[f.ravel()] = True
    same, rev = _duplicates(he.faces)

    w = _winding(v, he)
    h1, _ = w.inconsistent_pairs
    inc = he.undirected(h1)
    inc = inc[np.lexsort((inc[:, 1], inc[:, 0]))]

    return MeshReport(
        n_vertices=nv,
        n_faces=nf,
        unused_vertices=np.flatnonzero(~used).astype(np.intp),
        degenerate_faces=np.flatnonzero(deg).astype(np.intp),
        coincident_faces=np.flatnonzero(coincident).astype(np.intp),
        collinear_faces=np.flatnonzero(collinear).astype(np.intp),
        duplicate_faces=same,
        reversed_duplicate_faces=rev,
        boundary_edges=_boundary_edges(he),
        non_manifold_edges=_non_manifold_edges(he),
        non_manifold_vertices=_non_manifold_vertices(he),
        inconsistent_edges=inc,
        face_component=w.component,
        components=_component_reports(w),
        faces_to_flip=np.flatnonzero(w.flip).astype(np.intp),
        measures=measure(v, f, used),
        weld_distance=welded.distance,
        merged_vertices=welded.merged,
        welded_vertices=welded.welded,
        near_miss_edges=welded.near_edges,
        near_miss_distance=welded.near_distance,
        holes=_holes(w.rims),
    )


def _component_reports(w: _Winding) -> tuple[ComponentReport, ...]:
    """One `ComponentReport` a piece, from the winding's per-piece arrays."""
    nc = w.n_components
    sizes = np.bincount(w.component[w.component >= 0], minlength=nc)[:nc]
    flips = np.bincount(w.component[w.flip], minlength=nc)[:nc]
    comps = []
    for i in range(nc):
        consistent = bool(w.inconsistent[i] == 0)
        measurable = bool(w.closed[i]) and consistent
        judged_by = "volume" if w.solid[i] else "volume_over_holes" if w.encloses[i] else None
        outward: bool | None = None
        if measurable:  # out of the material: a positive volume, or a negative one for a cavity
            volume, error = float(w.volume[i]), float(w.volume_error[i])
            outward = None if abs(volume) <= error else (volume > 0) != bool(w.cavity[i])
        if w.encloses[i] and consistent:
            outward = bool(w.capped_volume[i] > 0)
        comps.append(
            ComponentReport(
                faces=int(sizes[i]),
                closed=bool(w.closed[i]),
                consistent=consistent,
                orientable=bool(w.orientable[i]),
                outward=outward,
                volume=w.enclosed_volume(i) if measurable else None,
                faces_to_flip=int(flips[i]),
                cavity=bool(w.cavity[i]),
                judged_by=judged_by,
            )
        )
    return tuple(comps)
