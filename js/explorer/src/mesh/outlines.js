/*
 * The outlines over the surface: the faces to flip (outlined), boundary and non-manifold edges
 * (thick), each in its role's colour, and the picked face. A side of a face is 3 * face + k,
 * the edge from corner k to corner k + 1.
 *
 * At rest the outlines are wide lines (LineSegments2); while the camera turns they are plain
 * 1-pixel lines, because a software renderer (SwiftShader) draws each wide-line segment as a
 * draw of its own.
 */
import { BufferAttribute, BufferGeometry, Color, LineBasicMaterial, LineSegments } from "three";
import { LineMaterial } from "three/addons/lines/LineMaterial.js";
import { LineSegments2 } from "three/addons/lines/LineSegments2.js";
import { LineSegmentsGeometry } from "three/addons/lines/LineSegmentsGeometry.js";

/**
 * Up to this many faces to flip, each is outlined; above, only the rims of their patches (the
 * sides no other face to flip shares). An inside-out model has every face to flip: outlining
 * each would draw three wide-line segments a face, and a picture all outline, when its back
 * colour already shows every face.
 */
export const OUTLINE_EACH_UP_TO = 2000;

/** Outlines of up to this many sides are wide lines at rest; more are drawn thin always. */
const WIDE_SIDES_UP_TO = 6000;
/** While the camera turns, outlines of more sides than this are not drawn at all. */
const TURNING_SIDES_UP_TO = 30000;

const ROLES = ["flipped", "boundary", "non_manifold"];

/** Segments (6 floats each) of the given face sides (pos: display positions, 3 per vertex). */
function sideSegments(pos, faces, sides) {
  const out = new Float32Array(6 * sides.length);
  for (let i = 0; i < sides.length; i++) {
    const h = sides[i];
    const a = faces[h];
    const b = faces[h % 3 === 2 ? h - 2 : h + 1];
    for (let k = 0; k < 3; k++) {
      out[6 * i + k] = pos[3 * a + k];
      out[6 * i + 3 + k] = pos[3 * b + k];
    }
  }
  return out;
}

/** The three sides of each face in the list. */
function allSides(list) {
  const out = new Int32Array(3 * list.length);
  for (let i = 0; i < list.length; i++) for (let k = 0; k < 3; k++) out[3 * i + k] = 3 * list[i] + k;
  return out;
}

/** The sides (3 * face + k) of the listed faces that no other listed face shares. */
function rimSides(faces, list, nVertices) {
  const first = new Map(); // an edge (either direction) -> the first side met on it, -1 once shared
  for (let i = 0; i < list.length; i++) {
    for (let k = 0; k < 3; k++) {
      const side = 3 * list[i] + k;
      const a = faces[side];
      const b = faces[3 * list[i] + ((k + 1) % 3)];
      const key = a < b ? a * nVertices + b : b * nVertices + a;
      first.set(key, first.has(key) ? -1 : side);
    }
  }
  return Int32Array.from([...first.values()].filter((side) => side >= 0)).sort();
}

/** The sides to draw for each fault of a mesh ({ faces, flipped, boundary, non_manifold }). */
export function faultSides(data, nVertices) {
  const flipped = data.flipped || new Int32Array(0);
  return {
    flipped: flipped.length > OUTLINE_EACH_UP_TO ? rimSides(data.faces, flipped, nVertices) : allSides(flipped),
    boundary: data.boundary || new Int32Array(0),
    non_manifold: data.non_manifold || new Int32Array(0),
  };
}

/**
 * scene -> { draw(pos, faces, sets), show(turning), showPicked(pos, faces, face), clearPicked(),
 * setColors(colorOf, pickColor), setResolution(width, height), clear(), dispose() }.
 */
export function createOutlines(scene) {
  const wideMaterials = {
    flipped: new LineMaterial({ linewidth: 2.5 }),
    boundary: new LineMaterial({ linewidth: 4 }),
    non_manifold: new LineMaterial({ linewidth: 4 }),
  };
  const thinMaterials = Object.fromEntries(ROLES.map((role) => [role, new LineBasicMaterial()]));
  const pickMaterial = new LineMaterial({ linewidth: 4 });
  let wide = {};
  let thin = {};
  let pickLine = null;

  /** The outlines of each fault's sides (`sets`: role -> sides), thin, and wide if few enough. */
  function draw(pos, faces, sets) {
    for (const [role, sides] of Object.entries(sets)) {
      if (!sides.length) continue;
      const segments = sideSegments(pos, faces, sides);
      const g = new BufferGeometry();
      g.setAttribute("position", new BufferAttribute(segments, 3));
      const t = new LineSegments(g, thinMaterials[role]);
      t.renderOrder = 1;
      t.userData.sides = sides.length;
      thin[role] = t;
      scene.add(t);
      if (sides.length > WIDE_SIDES_UP_TO) continue; // thin lines only, also at rest
      const w = new LineSegmentsGeometry();
      w.setPositions(segments);
      const l = new LineSegments2(w, wideMaterials[role]);
      l.renderOrder = 1;
      wide[role] = l;
      scene.add(l);
    }
  }

  /** At rest the wide outlines (thin where there are none); while turning thin ones, if not too many. */
  function show(turning) {
    for (const [role, t] of Object.entries(thin)) {
      if (wide[role]) wide[role].visible = !turning;
      t.visible = turning ? t.userData.sides <= TURNING_SIDES_UP_TO : !wide[role];
    }
  }

  function showPicked(pos, faces, face) {
    clearPicked();
    const g = new LineSegmentsGeometry();
    g.setPositions(sideSegments(pos, faces, allSides([face])));
    pickLine = new LineSegments2(g, pickMaterial);
    pickLine.renderOrder = 3;
    scene.add(pickLine);
  }

  function clearPicked() {
    if (!pickLine) return;
    scene.remove(pickLine);
    pickLine.geometry.dispose();
    pickLine = null;
  }

  function clear() {
    for (const l of [...Object.values(wide), ...Object.values(thin)]) {
      scene.remove(l);
      l.geometry.dispose();
    }
    wide = {};
    thin = {};
    clearPicked();
  }

  return {
    draw,
    show,
    showPicked,
    clearPicked,
    /** colorOf(role) -> a CSS colour of each fault's role; pickColor: the picked face's. */
    setColors(colorOf, pickColor) {
      for (const role of ROLES) {
        wideMaterials[role].color = new Color(colorOf(role));
        thinMaterials[role].color = new Color(colorOf(role));
      }
      pickMaterial.color = new Color(pickColor);
    },
    setResolution(width, height) {
      for (const m of [...Object.values(wideMaterials), pickMaterial]) m.resolution.set(width, height);
    },
    clear,
    dispose() {
      clear();
      for (const m of [...Object.values(wideMaterials), ...Object.values(thinMaterials), pickMaterial]) m.dispose();
    },
  };
}
