"""The site's 3D views for a reader who cannot see them: described, heard, driven by keyboard only.

One page load of the calculator, as a screen-reader user works: the accessibility tree names
the toolbar, its buttons, the view and its description; Tab and Enter look down the z axis;
Listen (after the description) plays U, V and N as tones whose pan, pitch and brightness
follow the vectors (Web Audio, instrumented here rather than listened to), never before it is
pressed; Shift+Tab reaches vertex C and the arrow keys move it across the line AB, and the live
description (the same words as ``trinormal.explorer.describe`` in Python) changes once per key
press, within half a second, from the front to the back; the flip turns the back into the
front again; the arrow keys on the focused view turn the camera underneath. With reduced
motion the view jumps; in forced colours the controls, the focus and the description stay
visible; every target is at least 24 px; axe-core finds nothing serious. Then the mesh page:
its view's description names the model, its pieces, the faces to flip and the face picked by
number.
"""

from __future__ import annotations

import math

from page_checks import axe_serious

from trinormal import triangle_normal
from trinormal.explorer.describe import describe

# every tone the page starts: the pan, the pitch and the filter's cutoff, in order
_RECORD_TONES = """
window.__tones = { pan: [], frequency: [], cutoff: [] };
const P = BaseAudioContext.prototype;
const spy = (make, param, key) => function () {
  const node = make.call(this);
  const set = node[param].setValueAtTime.bind(node[param]);
  node[param].setValueAtTime = (v, t) => { window.__tones[key].push(v); return set(v, t); };
  return node;
};
P.createStereoPanner = spy(P.createStereoPanner, "pan", "pan");
P.createOscillator = spy(P.createOscillator, "frequency", "frequency");
P.createBiquadFilter = spy(P.createBiquadFilter, "frequency", "cutoff");
"""

# each change of the description's text, with the time it happened
_COUNT_CHANGES = """() => {
  const el = document.querySelector('#tn-view .tnx-describe');
  window.__said = [];
  new MutationObserver(() => window.__said.push({ text: el.textContent, t: performance.now() }))
    .observe(el, { childList: true, characterData: true, subtree: true });
}"""

DESCRIPTION = "#tn-view .tnx-describe"


def _tab_to(page, selector: str, back: bool = False, limit: int = 80) -> None:
    """Press Tab (or Shift+Tab) until the focus is on `selector`."""
    for _ in range(limit):
        if page.evaluate("s => document.activeElement?.matches(s) ?? false", selector):
            return
        page.keyboard.press("Shift+Tab" if back else "Tab")
    raise AssertionError(f"Tab never reached {selector}")


def _said(page, text: str) -> None:
    page.wait_for_function(
        "([sel, text]) => document.querySelector(sel)?.textContent === text",
        arg=[DESCRIPTION, text],
    )


def _tones(vectors) -> dict[str, list[float]]:
    """The pan and pitch Listen gives each vector: x and 440 Hz times 2 to the y, of its direction."""
    units = []
    for v in vectors:
        length = math.sqrt(sum(x * x for x in v))
        units.append([x / length for x in v])
    return {"pan": [u[0] for u in units], "frequency": [440 * 2 ** u[1] for u in units]}


def _close(got: list[float], want: list[float]) -> bool:
    return len(got) == len(want) and all(abs(g - w) < 1e-6 for g, w in zip(got, want, strict=True))


def test_the_calculators_view_is_described_heard_and_driven_by_keyboard(page, server, traffic):
    page.set_viewport_size({"width": 1280, "height": 900})
    page.emulate_media(reduced_motion="reduce")
    page.add_init_script(_RECORD_TONES)
    page.goto(server + "calculator/")
    page.wait_for_selector("#tn-view[data-ready='true']")
    page.locator("#ax").focus()

    # the accessibility tree: a toolbar of named buttons, the view as a group, its description
    tree = page.locator("#tn-view").aria_snapshot()
    for line in ('toolbar "3D view"', 'button "View along the z axis"', 'button "Listen to U, V',
                 'group "3D view of the triangle ABC and its normal N', "- status:"):  # fmt: skip
        assert line in tree, (line, tree)
    described = page.locator("#tn-view .tnx-stage").get_attribute("aria-describedby")
    assert page.locator(f"#{described}").get_attribute("aria-live") == "polite"

    # Tab to the z button, Enter: looking down z, the front, A→B→C counter-clockwise
    _tab_to(page, '[aria-label="View along the z axis"]')
    page.keyboard.press("Enter")
    r = triangle_normal((0, 0, 0), (1, 0, 0), (0, 1, 0))
    _said(page, describe(r, (0, 0, 1)))
    assert page.evaluate("window.__tones.pan") == []  # nothing plays before Listen is pressed

    # Listen, after the description: U, V and N, in order, panned by x, pitched by y
    _tab_to(page, ".tnx-listen")
    page.keyboard.press("Enter")
    assert page.locator(".tnx-listen").get_attribute("aria-pressed") == "true"
    page.wait_for_function("window.__tones.pan.length === 3")
    tones = page.evaluate("window.__tones")
    want = _tones([r.u, r.v, r.unit_normal])
    assert _close(tones["pan"], want["pan"]) and _close(tones["frequency"], want["frequency"])
    up_brightness = tones["cutoff"][2]

    # back to C, arrow keys: C walks down to (0, 0.1, 0), then one key per change
    _tab_to(page, '[data-vertex="C"]', back=True)
    for _ in range(9):
        page.keyboard.press("ArrowDown")
    page.wait_for_function("document.getElementById('cy').value === '0.1'")
    _said(page, describe(triangle_normal((0, 0, 0), (1, 0, 0), (0, "0.1", 0)), (0, 0, 1)))
    page.evaluate(_COUNT_CHANGES)
    for y, count in (("0.0", 1), ("-0.1", 2)):
        pressed = page.evaluate("performance.now()")
        page.keyboard.press("ArrowDown")
        _said(page, describe(triangle_normal((0, 0, 0), (1, 0, 0), (0, y, 0)), (0, 0, 1)))
        said = page.evaluate("window.__said")
        assert len(said) == count, said  # once per change
        assert said[-1]["t"] - pressed < 500, said
    assert "No direction to describe" in said[0]["text"]
    assert "You see the back of the triangle" in said[1]["text"]
    assert "A→B→C turns clockwise" in said[1]["text"]
    # heard again after the change (Listen is on): N points down now, a duller tone
    page.wait_for_function("window.__tones.cutoff.length >= 6")
    assert page.evaluate("window.__tones.cutoff.at(-1)") < up_brightness

    # Shift+Tab back to the flip, Enter: the other order, the front again
    _tab_to(page, '[aria-label^="Flip the order"]', back=True)
    page.keyboard.press("Enter")
    flipped = triangle_normal((0, 0, 0), (1, 0, 0), (0, "-0.1", 0), winding="ACB")
    _said(page, describe(flipped, (0, 0, 1)))
    assert "A→C→B turns counter-clockwise" in describe(flipped, (0, 0, 1))

    # no drag needed to turn the view: Tab to it, the arrow keys take the camera underneath
    _tab_to(page, "#tn-view .tnx-stage")
    for _ in range(12):
        page.keyboard.press("ArrowDown")
    _said(page, describe(flipped, (0, 0, -1)))

    # targets of at least 24 x 24 px; axe-core clean with all of this on the page
    sizes = page.evaluate(
        """() => [...document.querySelectorAll('#tn-view button, #tn-view [data-vertex]')]
            .map(e => { const r = e.getBoundingClientRect();
                        return [e.getAttribute('aria-label') || e.textContent, r.width, r.height]; })"""
    )
    assert [s for s in sizes if s[1] < 24 or s[2] < 24] == [], sizes
    assert axe_serious(page, "calculator, after keyboard use") == []

    # forced colours: the focus ring, the pressed Listen and the description stay visible
    page.emulate_media(forced_colors="active")
    seen = page.evaluate(
        """() => {
          const style = (e) => getComputedStyle(e);
          const listen = document.querySelector('.tnx-listen');
          const other = document.querySelector('[aria-label="View along the z axis"]');
          const text = document.querySelector('#tn-view .tnx-describe');
          return {
            ring: style(document.activeElement).outlineStyle,
            pressed: style(listen).backgroundColor !== style(other).backgroundColor,
            text: text.getBoundingClientRect().height > 0 && style(text).color !== style(text).backgroundColor,
          };
        }"""
    )
    assert seen == {"ring": "solid", "pressed": True, "text": True}, seen
    assert not traffic.problems()
    assert not traffic.off_origin

    # the mesh page: its view's description names the model, its pieces, the faces to flip
    page.emulate_media(forced_colors="none")
    page.goto(server + "mesh/")
    page.wait_for_selector("#tn-mesh[data-ready='true']")
    page.locator("button[data-example]").first.focus()
    page.keyboard.press("Enter")
    page.wait_for_selector("#tn-mesh-view[data-ready='true']")
    words = page.locator("#tn-mesh-view .tnm-describe")
    words.wait_for()
    name = page.locator("#tn-mesh-name").inner_text()
    report = page.evaluate("JSON.parse(document.getElementById('tn-mesh').dataset.report)")
    text = words.inner_text()
    assert text.startswith(f"{name}: {report['n_faces']} faces in "), text
    flips = report["faces_to_flip"]
    assert ("No face needs flipping." in text) == (not flips), text
    assert page.locator("#tn-mesh-view .tnm-stage").get_attribute("aria-describedby") == (
        words.get_attribute("id")
    )
    # pick a face by its number, from the keyboard: the description says what is under it
    face = flips[0] if flips else 0
    box = page.locator("#tn-mesh-view input")
    box.focus()
    page.keyboard.type(str(face))
    page.keyboard.press("Enter")
    page.wait_for_function(
        "([sel, f]) => document.querySelector(sel).textContent.includes(`Picked: Face ${f}:`)",
        arg=["#tn-mesh-view .tnm-describe", face],
    )
    assert not traffic.problems()
