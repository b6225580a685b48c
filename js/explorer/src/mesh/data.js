/*
 * The mesh a host gives the view, as typed arrays: the site's "mesh" object as it is, or the
 * kernel's binary buffers (Jupyter, trinormal.mesh.widget.MeshView) read into typed arrays.
 */

/** A typed array over a binary buffer from the kernel (a DataView), copied if misaligned. */
function typed(Type, value) {
  if (!value) return new Type(0);
  if (ArrayBuffer.isView(value) && !(value instanceof DataView)) return value;
  const { buffer, byteOffset, byteLength } = value;
  if (byteOffset % Type.BYTES_PER_ELEMENT === 0) return new Type(buffer, byteOffset, byteLength / Type.BYTES_PER_ELEMENT);
  return new Type(buffer.slice(byteOffset, byteOffset + byteLength));
}

/** The mesh to draw: the host's "mesh" object (the site), or the kernel's buffers (Jupyter). */
export function readMesh(model) {
  const mesh = model.get("mesh");
  if (mesh) return mesh;
  const positions = model.get("positions");
  if (!positions || !positions.byteLength) return null;
  return {
    positions: typed(Float64Array, positions),
    faces: typed(Uint32Array, model.get("faces")),
    flipped: typed(Int32Array, model.get("flipped")),
    boundary: typed(Int32Array, model.get("boundary")),
    non_manifold: typed(Int32Array, model.get("non_manifold")),
    arrow_faces: typed(Int32Array, model.get("arrow_faces")),
    arrow_normals: typed(Float32Array, model.get("arrow_normals")),
    vertex_normals: typed(Float32Array, model.get("vertex_normals")),
  };
}

/** Centre and radius of the bounding box; a scale that brings the model to radius ~2. */
function framing(positions) {
  const lo = [Infinity, Infinity, Infinity];
  const hi = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3) {
    for (let k = 0; k < 3; k++) {
      const x = positions[i + k];
      if (x < lo[k]) lo[k] = x;
      if (x > hi[k]) hi[k] = x;
    }
  }
  if (!(lo[0] <= hi[0])) return { offset: [0, 0, 0], scale: 1 };
  const offset = lo.map((l, k) => (l + hi[k]) / 2);
  const radius = Math.hypot(hi[0] - lo[0], hi[1] - lo[1], hi[2] - lo[2]) / 2;
  return { offset, scale: radius > 0 && Number.isFinite(radius) ? 2 / radius : 1 };
}

/**
 * The positions in display units (Float32, centred, radius ~2), with the offset and scale that
 * take a display point back to the model's own coordinates: model = display / scale + offset.
 */
export function displayPositions(positions) {
  const { offset, scale } = framing(positions);
  const pos = new Float32Array(positions.length);
  for (let i = 0; i < pos.length; i++) pos[i] = (positions[i] - offset[i % 3]) * scale;
  return { pos, offset, scale };
}
