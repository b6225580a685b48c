/*
 * The mesh check's Web Worker: reads the file, checks it, fixes its winding and writes the
 * repaired file, off the page's main thread, so a million faces never freeze the page.
 *
 * Messages in: {op: "open", id, name, buffer} (the file's bytes, transferred),
 *              {op: "weld", id}, {op: "fix", id}.
 * Messages out: {id, type: "progress", stage, fraction},
 *               {id, type: "done", result}, {id, type: "error", message}.
 * The worker keeps the last mesh read; "weld" and "fix" work on it.
 */
/* global importScripts, TrinormalMesh */
self.window = self; // trinormal-constants.js sets window.TRINORMAL_CONSTANTS
importScripts(
  "trinormal-constants.js",
  "trinormal-core.js",
  "trinormal-mesh-base.js",
  "trinormal-mesh-read.js",
  "trinormal-mesh-weld.js",
  "trinormal-mesh-shells.js",
  "trinormal-mesh-check.js",
  "trinormal-mesh-write.js",
  "trinormal-mesh-print.js"
);

let current = null; // {mesh, faces, report, weld}

function post(id, type, extra, transfer) {
  self.postMessage(Object.assign({ id, type }, extra), transfer || []);
}

function progressFor(id, stage) {
  let last = -1;
  return (fraction) => {
    const f = Math.round(fraction * 100) / 100;
    if (f !== last) {
      last = f;
      post(id, "progress", { stage, fraction: f });
    }
  };
}

/** What the page needs: the report, and the mesh for the 3D view (copies, transferred). */
function payload(mesh, faces, report, file) {
  // float64: the view centres and scales the model before it rounds to float32, so models at
  // 1e-200 or 1e200 are drawn too
  const positions = new Float64Array(mesh.vertices);
  const faceCopy = new Uint32Array(faces);
  const result = {
    name: mesh.name,
    format: mesh.format,
    binary: !!mesh.binary,
    notes: mesh.notes,
    report: TrinormalMesh.toDict(report),
    positions,
    faces: faceCopy,
    boundary: report._boundary_sides,
    non_manifold: report._non_manifold_sides,
    flipped: new Int32Array(report.faces_to_flip),
  };
  const transfer = [positions.buffer, faceCopy.buffer, result.boundary.buffer, result.non_manifold.buffer, result.flipped.buffer];
  if (file) {
    result.file = file;
    transfer.push(file.buffer);
  }
  return [result, transfer];
}

/** Check `faces` of the mesh read (welded when asked); the worker keeps what it checked. */
function checked(id, mesh, faces, weld) {
  const report = TrinormalMesh.check(mesh.vertices, faces, progressFor(id, "check"), weld);
  current = { mesh, faces, report, weld };
  return report;
}

self.onmessage = (event) => {
  const { op, id } = event.data;
  try {
    if (op === "open") {
      const mesh = TrinormalMesh.read(event.data.buffer, event.data.name, progressFor(id, "read"));
      const [result, transfer] = payload(mesh, mesh.faces, checked(id, mesh, mesh.faces, false));
      post(id, "done", { result }, transfer);
    } else if (op === "weld") {
      if (!current) throw new Error("no mesh to weld");
      const mesh = current.mesh;
      const [result, transfer] = payload(mesh, mesh.faces, checked(id, mesh, mesh.faces, true));
      post(id, "done", { result }, transfer);
    } else if (op === "fix") {
      if (!current) throw new Error("no mesh to fix");
      const faces = TrinormalMesh.fixWinding(current.faces, current.report);
      const report = checked(id, current.mesh, faces, current.weld);
      const [result, transfer] = payload(current.mesh, faces, report, TrinormalMesh.write(current.mesh, faces));
      post(id, "done", { result }, transfer);
    }
  } catch (err) {
    if (err instanceof TrinormalMesh.MeshError) post(id, "error", { message: err.message });
    else post(id, "error", { message: TrinormalMesh.message("internal", { detail: String((err && err.message) || err) }) });
  }
};
