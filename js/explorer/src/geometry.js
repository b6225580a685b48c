/*
 * What is drawn: the triangle (front and back faces), its edges and winding ring, the
 * vertices, U and V from A, N from the centroid, the unit normal, the right-hand-rule cue,
 * the parallelogram, the axes with ticks, the grid, and the line of a degenerate triangle.
 * All sizes are in display units (the data divided by a power of ten, see index.js).
 */
import {
  BackSide,
  BufferAttribute,
  BufferGeometry,
  ConeGeometry,
  CylinderGeometry,
  DoubleSide,
  FrontSide,
  GridHelper,
  Group,
  Matrix4,
  Mesh,
  MeshBasicMaterial,
  SphereGeometry,
  TorusGeometry,
  Vector3,
} from "three";
import { farthestPair } from "./framing.js";

const Y = new Vector3(0, 1, 0);
const tmp = new Vector3();

export class Drawing {
  constructor(scene) {
    this.root = new Group();
    scene.add(this.root);
    this.owned = [];
    this.materials = {};
    this.cylinder = this.own(new CylinderGeometry(1, 1, 1, 18, 1).translate(0, 0.5, 0));
    this.cone = this.own(new ConeGeometry(1, 1, 24, 1).translate(0, 0.5, 0));
    this.sphere = this.own(new SphereGeometry(1, 28, 18));

    // faces: the side N points out of is drawn in `front`, the other in `back`
    this.triGeometry = this.own(new BufferGeometry());
    this.triGeometry.setAttribute("position", new BufferAttribute(new Float32Array(9), 3));
    this.front = this.add(new Mesh(this.triGeometry, this.material("front", { side: FrontSide, offset: true })));
    this.back = this.add(new Mesh(this.triGeometry, this.material("back", { side: BackSide, offset: true })));
    this.paraGeometry = this.own(new BufferGeometry());
    this.paraGeometry.setAttribute("position", new BufferAttribute(new Float32Array(18), 3));
    this.para = this.add(
      new Mesh(this.paraGeometry, this.material("para", { side: DoubleSide, opacity: 0.28 })),
    );
    this.paraEdges = [this.stick("paraEdge"), this.stick("paraEdge")];

    this.edges = [this.stick("edge"), this.stick("edge"), this.stick("edge")];
    this.ring = [0, 1, 2].map(() => this.add(new Mesh(this.cone, this.material("ring"))));
    this.vertices = {};
    for (const name of "ABC") this.vertices[name] = this.add(new Mesh(this.sphere, this.material(name)));
    this.u = this.arrow("U");
    this.v = this.arrow("V");
    this.n = this.arrow("N");
    this.unit = this.arrow("unit", { opacity: 0.45 }); // a sleeve: N stays visible inside it
    this.cue = new Group();
    this.root.add(this.cue);
    this.cueArc = new Mesh(undefined, this.material("N"));
    this.cueHead = new Mesh(this.cone, this.material("N"));
    this.cueHead.rotation.z = -Math.PI / 2; // cone along +x: the arc's tangent at its end
    this.cue.add(this.cueArc, this.cueHead);
    this.arcs = new Map();
    this.line = this.stick("line");
    this.axes = {};
    for (const a of "xyz") this.axes[a] = { arrow: this.arrow(a), ticks: [] };
    this.grid = null;
  }

  own(thing) {
    this.owned.push(thing);
    return thing;
  }

  add(object) {
    this.root.add(object);
    return object;
  }

  material(role, { side = FrontSide, opacity = 1, offset = false } = {}) {
    const key = role + ":" + side + ":" + opacity + ":" + offset;
    if (!this.materials[key]) {
      const m = new MeshBasicMaterial({ side, transparent: opacity < 1, opacity, depthWrite: opacity >= 1 });
      if (offset) Object.assign(m, { polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
      m.userData.role = role;
      this.materials[key] = m;
    }
    return this.materials[key];
  }

  /** Set every material's colour: colors(role) -> "#rrggbb". */
  paint(colors) {
    for (const m of Object.values(this.materials)) m.color.set(colors(m.userData.role));
  }

  arrow(role, options = {}) {
    const group = new Group();
    const shaft = new Mesh(this.cylinder, this.material(role, options));
    const head = new Mesh(this.cone, this.material(role, options));
    group.add(shaft, head);
    this.root.add(group);
    return { group, shaft, head };
  }

  stick(role) {
    return this.add(new Mesh(this.cylinder, this.material(role)));
  }

  /** Place a cylinder from p to q with radius r. */
  static placeStick(mesh, p, q, r) {
    tmp.subVectors(q, p);
    const len = tmp.length();
    mesh.visible = len > 0;
    if (!len) return;
    mesh.position.copy(p);
    mesh.quaternion.setFromUnitVectors(Y, tmp.divideScalar(len));
    mesh.scale.set(r, len, r);
  }

  /** Place an arrow from p to q: shaft radius r, head 2.6 r wide, at most 45 % of the length. */
  static placeArrow(arrow, p, q, r, visible = true) {
    const d = new Vector3().subVectors(q, p);
    const len = d.length();
    arrow.group.visible = visible && len > 0;
    if (!arrow.group.visible) return;
    const headLen = Math.min(7 * r, 0.45 * len);
    const headR = Math.min(2.6 * r, headLen * 0.5);
    arrow.group.position.copy(p);
    arrow.group.quaternion.setFromUnitVectors(Y, d.divideScalar(len));
    arrow.shaft.scale.set(r, len - headLen * 0.9, r);
    arrow.head.position.set(0, len - headLen, 0);
    arrow.head.scale.set(headR, headLen, headR);
  }

  /** The axes from -L to L with ticks every t, and the grid in the plane z = 0. */
  setAxes(L, t, r, colors, show) {
    const ticks = [];
    for (const a of "xyz") {
      const e = new Vector3(a === "x" ? 1 : 0, a === "y" ? 1 : 0, a === "z" ? 1 : 0);
      const axis = this.axes[a];
      Drawing.placeArrow(axis.arrow, e.clone().multiplyScalar(-L), e.clone().multiplyScalar(L), r, show);
      const n = show ? Math.floor(L / t + 1e-9) : 0;
      while (axis.ticks.length < 2 * n) axis.ticks.push(this.add(new Mesh(this.sphere, this.material(a))));
      axis.ticks.forEach((m, i) => {
        const k = i < n ? i + 1 : -(i - n + 1);
        m.visible = i < 2 * n && Math.abs(k * t) < L - 1e-9;
        m.position.copy(e).multiplyScalar(k * t);
        m.scale.setScalar(r * 1.9);
        if (m.visible && k > 0) ticks.push({ axis: a, value: k * t, position: m.position.clone() });
      });
    }
    return ticks;
  }

  setGrid(L, t, colors, show) {
    if (this.grid) {
      this.root.remove(this.grid);
      this.grid.geometry.dispose();
      this.grid.material.dispose();
      this.grid = null;
    }
    if (!show) return;
    const divisions = Math.max(2, Math.round((4 * L) / t));
    this.grid = new GridHelper(2 * L, divisions, colors.gridMajor, colors.grid);
    this.grid.rotation.x = Math.PI / 2;
    this.grid.material.depthWrite = false;
    this.grid.renderOrder = -1;
    this.root.add(this.grid);
  }

  /**
   * Draw a triangle. g holds display-unit Vector3s: A, B, C, P, Q (U = P - A, V = Q - A in the
   * current winding), centroid, nDraw (N as drawn), unitDraw (or null), degenerate,
   * showParallelogram, r (the arrow radius).
   */
  update(g) {
    const { A, P, Q, centroid, r } = g;
    const pos = this.triGeometry.attributes.position;
    [A, P, Q].forEach((p, i) => pos.setXYZ(i, p.x, p.y, p.z));
    pos.needsUpdate = true;
    this.triGeometry.computeBoundingSphere();
    this.front.visible = this.back.visible = !g.degenerate;

    for (const name of "ABC") {
      const m = this.vertices[name];
      m.position.copy(g[name]);
      m.scale.setScalar(r * (g.degenerate ? 3.4 : 2.5));
    }
    const order = [A, P, Q];
    for (let i = 0; i < 3; i++) {
      const p = order[i];
      const q = order[(i + 1) % 3];
      Drawing.placeStick(this.edges[i], p, q, r * 0.45);
      // the ring: a small arrowhead at each edge's midpoint, pulled towards the centroid
      const cone = this.ring[i];
      const d = new Vector3().subVectors(q, p);
      const len = d.length();
      cone.visible = !g.degenerate && len > 0;
      if (cone.visible) {
        const size = Math.min(4.5 * r, 0.22 * len);
        const mid = new Vector3().addVectors(p, q).multiplyScalar(0.5).lerp(centroid, 0.22);
        cone.quaternion.setFromUnitVectors(Y, d.divideScalar(len));
        cone.position.copy(mid).addScaledVector(d, -size / 2);
        cone.scale.set(size * 0.45, size, size * 0.45);
      }
    }

    Drawing.placeArrow(this.u, A, P, r);
    Drawing.placeArrow(this.v, A, Q, r);
    const nTip = centroid.clone().add(g.nDraw);
    Drawing.placeArrow(this.n, centroid, nTip, r * 1.15, !g.degenerate);
    Drawing.placeArrow(
      this.unit,
      centroid,
      g.unitDraw ? centroid.clone().add(g.unitDraw) : centroid,
      r * 1.9,
      !g.degenerate && !!g.unitDraw,
    );
    this.updateCue(g);
    this.updateParallelogram(g);
    this.updateLine(g);
  }

  /** A curved arrow around N from U's direction to V's: the right-hand rule. */
  updateCue(g) {
    const n = g.nDraw.clone();
    const nLen = n.length();
    if (g.degenerate || !nLen) {
      this.cue.visible = false;
      return;
    }
    n.divideScalar(nLen);
    const U = new Vector3().subVectors(g.P, g.A);
    const V = new Vector3().subVectors(g.Q, g.A);
    const e1 = U.clone().addScaledVector(n, -U.dot(n)).normalize();
    const e2 = new Vector3().crossVectors(n, e1);
    let angle = Math.atan2(V.dot(e2), V.dot(e1));
    if (!(angle > 0)) angle = Math.PI / 2;
    angle = Math.max(angle, 0.45 * Math.PI);
    // one arc per 5 degrees, made once: a drag changes the angle every frame
    const step = Math.PI / 36;
    const key = Math.round(angle / step);
    if (!this.arcs.has(key)) this.arcs.set(key, new TorusGeometry(1, 0.055, 8, 48, key * step));
    this.cueArc.geometry = this.arcs.get(key);
    const a = key * step;
    this.cueHead.position.set(Math.cos(a), Math.sin(a), 0);
    this.cueHead.rotation.set(0, 0, a); // cone (+y) turned to the tangent (-sin a, cos a)
    this.cueHead.position.addScaledVector(new Vector3(-Math.sin(a), Math.cos(a), 0), -0.12);
    this.cueHead.scale.set(0.16, 0.32, 0.16);
    const radius = 0.32 * Math.min(U.length(), V.length(), 1.2 * nLen) + 1e-9;
    const basis = new Matrix4().makeBasis(e1, e2, n);
    this.cue.quaternion.setFromRotationMatrix(basis);
    this.cue.position.copy(g.centroid).addScaledVector(n, 0.3 * nLen);
    this.cue.scale.setScalar(Math.max(radius, 3 * g.r));
    this.cue.visible = true;
  }

  updateParallelogram(g) {
    const show = g.showParallelogram && !g.degenerate;
    this.para.visible = show;
    this.paraEdges.forEach((e) => (e.visible = show));
    if (!show) return;
    const D = new Vector3().addVectors(g.P, g.Q).sub(g.A);
    const pos = this.paraGeometry.attributes.position;
    // the half the triangle does not cover (the triangle keeps its own colours)
    [g.P, D, g.Q, g.P, D, g.Q].forEach((p, i) => pos.setXYZ(i, p.x, p.y, p.z));
    pos.needsUpdate = true;
    this.paraGeometry.computeBoundingSphere();
    Drawing.placeStick(this.paraEdges[0], g.P, D, g.r * 0.45);
    Drawing.placeStick(this.paraEdges[1], g.Q, D, g.r * 0.45);
  }

  /** For a degenerate triangle: the line through its points (none when they coincide). */
  updateLine(g) {
    this.line.visible = false;
    if (!g.degenerate) return;
    const { ends, far } = farthestPair([g.A, g.B, g.C]);
    if (!ends || far < g.r) return;
    const dir = new Vector3().subVectors(ends[1], ends[0]).normalize();
    const ext = Math.max(0.35 * far, 6 * g.r);
    const p = ends[0].clone().addScaledVector(dir, -ext);
    const q = ends[1].clone().addScaledVector(dir, ext);
    Drawing.placeStick(this.line, p, q, g.r * 0.9);
  }

  dispose() {
    this.setGrid(0, 1, null, false);
    for (const g of this.arcs.values()) g.dispose();
    for (const g of this.owned) g.dispose();
    for (const m of Object.values(this.materials)) m.dispose();
    this.root.removeFromParent();
  }
}

