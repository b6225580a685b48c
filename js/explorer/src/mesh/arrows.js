/*
 * Normals drawn as short arrows (Jupyter only: the kernel sends them): each sampled face's unit
 * normal from its centre (arrow_faces, arrow_normals), and the vertex normals from a sample of
 * the vertices (vertex_normals). Degenerate faces and zero vertex normals get no arrow.
 */
import { BufferAttribute, BufferGeometry, Color, LineBasicMaterial, LineSegments, Vector3 } from "three";

/** Most vertex-normal arrows drawn (a sample of the vertices on bigger models). */
const MAX_VERTEX_ARROWS = 1500;

/** Arrow segments (shaft and two barbs, 18 floats each) from points along unit directions. */
function arrowSegments(starts, dirs, length) {
  const n = starts.length / 3;
  const out = new Float32Array(18 * n);
  let w = 0;
  const d = new Vector3();
  const side = new Vector3();
  const up = new Vector3();
  for (let i = 0; i < n; i++) {
    d.set(dirs[3 * i], dirs[3 * i + 1], dirs[3 * i + 2]);
    if (!(d.lengthSq() > 0)) continue; // a degenerate face or a zero vertex normal: no arrow
    d.normalize();
    const x = starts[3 * i];
    const y = starts[3 * i + 1];
    const z = starts[3 * i + 2];
    const tx = x + d.x * length;
    const ty = y + d.y * length;
    const tz = z + d.z * length;
    up.set(Math.abs(d.z) < 0.9 ? 0 : 1, 0, Math.abs(d.z) < 0.9 ? 1 : 0);
    side.crossVectors(d, up).normalize().multiplyScalar(0.22 * length);
    const bx = tx - d.x * 0.35 * length;
    const by = ty - d.y * 0.35 * length;
    const bz = tz - d.z * 0.35 * length;
    out.set([x, y, z, tx, ty, tz, tx, ty, tz, bx + side.x, by + side.y, bz + side.z, tx, ty, tz, bx - side.x, by - side.y, bz - side.z], w);
    w += 18;
  }
  return out.subarray(0, w);
}

/** Every k-th index below n, so that at most `most` are taken. */
function sample(n, most) {
  const step = Math.max(1, Math.ceil(n / most));
  const out = new Int32Array(Math.ceil(n / step));
  for (let i = 0, j = 0; i < n; i += step, j++) out[j] = i;
  return out;
}

/** The median edge length of a sample of faces (display units): the arrows' length scale. */
function typicalEdge(pos, faces) {
  const picks = sample(faces.length / 3, 2000);
  const lengths = [];
  for (const f of picks) {
    const a = faces[3 * f];
    const b = faces[3 * f + 1];
    lengths.push(Math.hypot(pos[3 * a] - pos[3 * b], pos[3 * a + 1] - pos[3 * b + 1], pos[3 * a + 2] - pos[3 * b + 2]));
  }
  lengths.sort((p, q) => p - q);
  return lengths.length ? lengths[lengths.length >> 1] : 0.1;
}

/** The starts (each face's centre) and directions of the face arrows, or null without them. */
function faceArrows(data, pos) {
  const af = data.arrow_faces || new Int32Array(0);
  const an = data.arrow_normals || new Float32Array(0);
  if (!af.length || an.length !== 3 * af.length) return null;
  const starts = new Float32Array(3 * af.length);
  for (let i = 0; i < af.length; i++) {
    for (let c = 0; c < 3; c++) {
      const v = data.faces[3 * af[i] + c];
      for (let k = 0; k < 3; k++) starts[3 * i + k] += pos[3 * v + k] / 3;
    }
  }
  return { starts, dirs: an };
}

/** The starts and directions of the vertex arrows (a sample), or null without vertex normals. */
function vertexArrows(data, pos) {
  const vn = data.vertex_normals;
  if (!vn || vn.length !== pos.length) return null;
  const picks = sample(pos.length / 3, MAX_VERTEX_ARROWS);
  const starts = new Float32Array(3 * picks.length);
  const dirs = new Float32Array(3 * picks.length);
  picks.forEach((v, i) => {
    for (let k = 0; k < 3; k++) {
      starts[3 * i + k] = pos[3 * v + k];
      dirs[3 * i + k] = vn[3 * v + k];
    }
  });
  return { starts, dirs };
}

/**
 * scene -> { draw(data, pos), has(kind), count(kind), show(kind, on), setColors(face, vertex),
 * clear(), dispose() }; kind is "face" or "vertex".
 */
export function createArrows(scene) {
  const materials = { face: new LineBasicMaterial(), vertex: new LineBasicMaterial() };
  let arrows = {};

  function lines(segments, material) {
    const g = new BufferGeometry();
    g.setAttribute("position", new BufferAttribute(segments, 3));
    const l = new LineSegments(g, material);
    l.renderOrder = 2;
    scene.add(l);
    return l;
  }

  function draw(data, pos) {
    const length = 0.5 * typicalEdge(pos, data.faces);
    for (const [kind, found] of [["face", faceArrows(data, pos)], ["vertex", vertexArrows(data, pos)]]) {
      if (found) arrows[kind] = lines(arrowSegments(found.starts, found.dirs, length), materials[kind]);
    }
  }

  function clear() {
    for (const a of Object.values(arrows)) {
      scene.remove(a);
      a.geometry.dispose();
    }
    arrows = {};
  }

  return {
    draw,
    has: (kind) => Boolean(arrows[kind]),
    /** How many arrows of a kind are drawn (6 points each). */
    count: (kind) => (arrows[kind] ? arrows[kind].geometry.getAttribute("position").count / 6 : 0),
    show(kind, on) {
      if (arrows[kind]) arrows[kind].visible = on;
    },
    setColors(face, vertex) {
      materials.face.color = new Color(face);
      materials.vertex.color = new Color(vertex);
    },
    clear,
    dispose() {
      clear();
      for (const m of Object.values(materials)) m.dispose();
    },
  };
}
