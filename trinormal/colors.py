"""One colour code for the points, the edges and the normal, everywhere.

The 3D explorer, every matplotlib figure and the site draw A, B, C, U, V and N
in these colours. Each role has a colour for light backgrounds and one for dark
backgrounds; both keep a contrast of at least 3:1 against their background
(WCAG's rule for graphics), and the hues come from Okabe and Ito's palette, so
the code survives the common forms of colour blindness. The x, y and z axes are
neutral greys (lighter from x to z), so no axis shares a colour with U, V, N
or a face side. Colour is never the only cue: every point, arrow, face and axis
is also labelled. The mesh view of the
site's "Check a mesh" page adds three roles drawn over a mesh's faces (faces to
flip, boundary edges, non-manifold edges); its legend names each with its count.

Examples
--------
>>> ROLE_COLORS["N"]
'#007A5A'
>>> color("N", dark=True)
'#3DDC97'
>>> sorted(ROLES) == sorted(ROLE_COLORS)
True
"""

from __future__ import annotations

__all__ = [
    "COLOR_CODE",
    "DARK_ROLE_COLORS",
    "ROLES",
    "ROLE_COLORS",
    "ROLE_MEANINGS",
    "color",
    "palette",
]

#: What each role is, in the words the readouts use.
ROLE_MEANINGS: dict[str, str] = {
    "A": "vertex A",
    "B": "vertex B",
    "C": "vertex C",
    "U": "edge U, from A",
    "V": "edge V, from A",
    "N": "normal N = U × V",
    "front": "front face (N points out of it)",
    "back": "back face",
    "x": "x axis",
    "y": "y axis",
    "z": "z axis",
    "flipped": "outline of a mesh face wound against its neighbours (to flip)",
    "boundary": "mesh edge with one face only (the rim of a hole)",
    "non_manifold": "mesh edge shared by three faces or more",
}

#: The colour code in words, as notebooks 01 and 03 state it (a test holds them to it).
COLOR_CODE = (
    "U vermillion, V blue, N green; the face yellow where you see its front (the side N "
    "points out of) and sky blue where you see its back; the points A dark grey, B amber "
    "(U ends at B), C purple (V ends at C); the axes neutral (greys, or black lines in the "
    "drawn figures), never a vector's colour, and named x, y and z (in the explorer's 3D "
    "view, at their ends)."
)

#: The roles, in drawing order.
ROLES: tuple[str, ...] = tuple(ROLE_MEANINGS)

#: Colours on a light (white) background.
ROLE_COLORS: dict[str, str] = {
    "A": "#333333",  # neutral: the vertex both edges start from
    "B": "#A85A00",  # dark amber, of U's family (U ends at B)
    "C": "#7A3E9D",  # purple, of V's family (V ends at C)
    "U": "#D55E00",  # Okabe-Ito vermillion
    "V": "#0072B2",  # Okabe-Ito blue
    "N": "#007A5A",  # Okabe-Ito bluish green, darkened for 5:1 on white
    "front": "#F0E442",  # Okabe-Ito yellow: the face N points out of
    "back": "#56B4E9",  # Okabe-Ito sky blue: the other side
    # the axes are neutral greys, told apart by lightness and named at their ends: no axis
    # shares a hue with U, V, N or a face side
    "x": "#4D4D4D",
    "y": "#6E6E6E",
    "z": "#8C8C8C",
    # a mesh's defects, drawn over its faces (the mesh view of the site's "Check a mesh" page)
    "flipped": "#000000",
    "boundary": "#C1007C",  # Okabe-Ito reddish purple, darkened: 4.5:1 on the front yellow
    "non_manifold": "#D55E00",
}

#: Colours on a dark background (the site's slate scheme, a dark JupyterLab theme).
DARK_ROLE_COLORS: dict[str, str] = {
    "A": "#E6E6E6",
    "B": "#F5A623",
    "C": "#D4A6F0",
    "U": "#FF8C42",
    "V": "#56B4E9",
    "N": "#3DDC97",
    "front": "#E5D740",
    "back": "#3A8FC4",
    "x": "#D0D0D0",
    "y": "#ABABAB",
    "z": "#8A8A8A",
    "flipped": "#FFFFFF",
    "boundary": "#FF6EC7",
    "non_manifold": "#FF8C42",
}


def color(role: str, dark: bool = False) -> str:
    """Return the colour of one role.

    Parameters
    ----------
    role : str
        One of `ROLES`: ``"A"``, ``"B"``, ``"C"``, ``"U"``, ``"V"``,
        ``"N"``, ``"front"``, ``"back"``, ``"x"``, ``"y"`` or ``"z"``.
    dark : bool, default False
        The variant for a dark background.

    Returns
    -------
    str
        A ``#RRGGBB`` colour.

    Raises
    ------
    KeyError
        For an unknown role.

    Examples
    --------
    >>> color("U"), color("U", dark=True)
    ('#D55E00', '#FF8C42')
    """
    return (DARK_ROLE_COLORS if dark else ROLE_COLORS)[role]


def palette() -> dict[str, dict[str, str]]:
    """Every role's light and dark colour, as the 3D view and the site read them.

    Returns
    -------
    dict
        ``{role: {"light": "#RRGGBB", "dark": "#RRGGBB"}}`` for every role.

    Examples
    --------
    >>> palette()["V"]
    {'light': '#0072B2', 'dark': '#56B4E9'}
    """
    return {r: {"light": ROLE_COLORS[r], "dark": DARK_ROLE_COLORS[r]} for r in ROLES}
