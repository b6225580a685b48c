"""`Explorer.to_png`: the 3D view's own picture for the current state, else the snapshot.

The kernel's side is driven as the browser drives it, with the custom message the view sends
(``{"picture": {...}}`` and the PNG as a buffer); the view's side (js/explorer/src/topng.js)
runs under Node with a fake stage.
"""

from __future__ import annotations

import io
import json
import subprocess
from pathlib import Path
from typing import Any

from node_runs import node_path
from PIL import Image

from trinormal.explorer import Explorer, ExplorerView
from trinormal.explorer.widget import PICTURE_FIELDS

SNAPSHOT_SIZE = (648, 288)


def png_of(width: int, height: int) -> bytes:
    out = io.BytesIO()
    Image.new("RGB", (width, height), "white").save(out, format="PNG")
    return out.getvalue()


def size_of(png: bytes) -> tuple[int, int]:
    return Image.open(io.BytesIO(png)).size


def shown(ex: Explorer, **changes: Any) -> dict[str, Any]:
    """The values the view names in its picture message: the kernel's, with ``changes``."""
    values = {name: getattr(ex.view, name) for name in PICTURE_FIELDS}
    return json.loads(json.dumps({**values, **changes}))  # as they arrive: JSON


def send_picture(ex: Explorer, values: dict[str, Any], png: bytes) -> None:
    """The view's picture message, through the widget's message handlers (as from a browser)."""
    ex.view._handle_custom_msg({"picture": values}, [memoryview(png)])


def test_to_png_is_the_views_picture_of_the_current_state_and_else_the_snapshot():
    ex = Explorer(a=("0.1", "0.2", "0.3"), b=("1/3", 0, 0), c=(0, "2.35", 0))
    assert ex.view.send_pictures and not ExplorerView().send_pictures
    assert ex.picture_source == "snapshot" and size_of(ex.to_png()) == SNAPSHOT_SIZE
    view_png = png_of(1200, 800)
    # a picture of another triangle (the view drew a value the kernel has not taken): not this one
    send_picture(ex, shown(ex, c=["0", "2.4", "0"]), view_png)
    assert ex.picture_source == "snapshot" and size_of(ex.to_png()) == SNAPSHOT_SIZE
    send_picture(ex, shown(ex), view_png)
    assert ex.picture_source == "view" and ex.to_png() == view_png
    # a cell changes the state: until the view draws it, the snapshot of the new state
    ex.set(c=(0, "2.4", 0))
    assert ex.picture_source == "snapshot" and size_of(ex.to_png()) == SNAPSHOT_SIZE
    ex.set(c=(0, "2.35", 0))  # the state the view's picture shows, again
    assert ex.to_png() == view_png
    for change in ({"winding": "ACB"}, {"show_parallelogram": True}, {"show_unit_normal": True}):
        ex.view.set_trait(*next(iter(change.items())))
        assert ex.picture_source == "snapshot", change
        send_picture(ex, shown(ex), view_png)
        assert ex.picture_source == "view", change
    # the picture is kept per explorer, not shared
    assert Explorer(a=("0.1", "0.2", "0.3"), b=("1/3", 0, 0), c=(0, "2.35", 0)).picture_source == (
        "snapshot"
    )


def test_a_message_without_a_png_changes_nothing():
    ex = Explorer()
    view_png = png_of(800, 600)
    send_picture(ex, shown(ex), view_png)
    for buffers in ([], [b"GIF89a"]):
        ex.view._handle_custom_msg({"picture": shown(ex, a=["1", "1", "1"])}, buffers)
        assert ex.to_png() == view_png
    ex.view._handle_custom_msg({"picture": "a"}, [memoryview(png_of(10, 10))])
    assert ex.to_png() == view_png
    # the view's other message still lands beside it
    ex.view._handle_custom_msg({"viewer": [0, 0, -1]}, [])
    assert "back of the triangle" in ex.describe()


def test_the_view_sends_one_picture_per_settled_change():
    # js/explorer/src/topng.js under Node, with a fake stage and model
    node = node_path()
    check = Path(__file__).with_name("topng_check.mjs")
    out = json.loads(
        subprocess.run([node, str(check)], capture_output=True, text=True, check=True).stdout
    )
    first = {"a": ["0", "0", "0"], "b": ["1", "0", "0"], "c": ["0", "1", "0"], "winding": "ABC",
             "show_parallelogram": False, "show_unit_normal": False}  # fmt: skip
    # three frames, then quiet: one picture (the frames it draws itself are no change)
    assert out["first"] == {"takes": 1, "sent": 1}
    assert out["message"] == {"picture": first} and sorted(first) == sorted(PICTURE_FIELDS)
    assert out["buffer"] == [0x89, 0x50, 0x4E, 0x47, 1]
    assert out["root"] == {"values": first, "width": 400, "height": 300}
    assert out["unchanged"] == {"takes": 1, "sent": 1}
    assert out["duringDrag"] == {"takes": 1, "sent": 1}
    assert out["afterDrag"] == {"takes": 2, "sent": 2} and out["dragged"] == ["0", "1.5", "0"]
    assert out["duringTurn"] == {"takes": 2, "sent": 2}
    assert out["afterTurn"] == {"takes": 3, "sent": 3}
    assert out["resizedAndFlipped"] == {"takes": 5, "sent": 5} and out["flipped"] == "ACB"
    assert out["hiddenOrOff"] == {"takes": 5, "sent": 5}
    assert out["stopped"] == {"takes": 5, "sent": 5} and out["listeners"] == []
