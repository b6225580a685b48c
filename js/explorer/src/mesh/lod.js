/*
 * Level of detail while the camera turns. A model of more than COARSE_ABOVE faces is drawn as
 * a coarser copy of about COARSE_FACES faces while the pointer turns it, and in full again as
 * soon as it is released; the outlines are drawn thin meanwhile (outlines.js). On a software
 * renderer the frame time grows with the faces drawn, not with the pixels
 * (benchmarks/bench_mesh_view.py measures it). A click that picks a face, without moving the
 * camera, keeps the full model.
 */
import { BufferAttribute, BufferGeometry, Mesh } from "three";
import { MeshoptSimplifier } from "meshoptimizer/simplifier";
import { listen } from "../dom.js";

const COARSE_ABOVE = 60000;
const COARSE_FACES = 30000;

/** The rows (3 floats) of `values` a compacted copy keeps: row i goes to row remap[i]. */
function keptRows(values, remap, unique) {
  const out = new Float32Array(3 * unique);
  for (let i = 0; i < remap.length; i++) {
    const j = remap[i];
    if (j === 0xffffffff) continue; // not used by the copy
    out[3 * j] = values[3 * i];
    out[3 * j + 1] = values[3 * i + 1];
    out[3 * j + 2] = values[3 * i + 2];
  }
  return out;
}

/**
 * The index of a coarser copy of the mesh (faces: Uint32, pos: Float32 display positions), or
 * null. meshoptimizer's simplify collapses edges where that changes the shape least and refuses
 * a collapse that turns a face over, so each side keeps its colour (simplifySloppy's grid
 * merging leaves specks of the wrong colour). On a model wound every which way nearly every
 * collapse turns a face over and simplify keeps most faces: there the colours are speckled
 * anyway, and the sloppy copy is taken.
 */
function coarseIndex(faces, pos) {
  const index = new Uint32Array(faces.buffer, faces.byteOffset, faces.length);
  let [kept] = MeshoptSimplifier.simplify(index, pos, 3, 3 * COARSE_FACES, 1);
  if (kept.length > 6 * COARSE_FACES) [kept] = MeshoptSimplifier.simplifySloppy(index, pos, 3, null, 3 * COARSE_FACES, 1);
  return kept.length ? kept : null;
}

/**
 * { stage, surface, outlines, root } -> { draw(faces, pos), clear(), dispose() }. `surface` is
 * surface.js's; `root` gets data-turning ("true" while the camera turns) and data-coarse-faces.
 */
export function createLod({ stage, surface, outlines, root }) {
  const scene = stage.scene;
  let coarse = null;
  let turning = false;
  let held = false; // the pointer is down on the view (OrbitControls' start .. end)

  /** Make the coarser copy of a big model, once meshoptimizer's WebAssembly is ready. */
  function draw(faces, pos) {
    if (faces.length / 3 <= COARSE_ABOVE) return;
    const full = surface.geometry();
    MeshoptSimplifier.ready.then(() => {
      if (surface.geometry() !== full || !MeshoptSimplifier.supported) return; // another model by now
      const kept = coarseIndex(faces, pos);
      if (!kept) return;
      // only the vertices the copy uses (fewer vertices to transform every frame)
      const [remap, unique] = MeshoptSimplifier.compactMesh(kept);
      const g = new BufferGeometry();
      g.setAttribute("position", new BufferAttribute(keptRows(full.getAttribute("position").array, remap, unique), 3));
      g.setIndex(new BufferAttribute(kept, 1));
      g.boundingSphere = full.boundingSphere;
      coarse = new Mesh(g, surface.material);
      coarse.userData = { remap, unique, normal: null };
      coarse.visible = false;
      scene.add(coarse);
      root.dataset.coarseFaces = String(kept.length / 3);
    });
  }

  /** While the camera turns: the coarser copy (if any) and thin outlines; else the model itself. */
  function showTurning(on) {
    const geometry = surface.geometry();
    if (!geometry || turning === on) return;
    turning = on;
    outlines.show(on);
    root.dataset.turning = String(on);
    stage.requestRender();
    if (!coarse) return;
    const normal = geometry.getAttribute("normal"); // smooth shading: the model's own normals
    const own = coarse.userData;
    if (normal && own.normal !== normal) {
      own.normal = normal;
      coarse.geometry.setAttribute("normal", new BufferAttribute(keptRows(normal.array, own.remap, own.unique), 3));
    }
    coarse.visible = on;
    surface.mesh().visible = !on;
  }

  const unlisten = listen(stage.controls, {
    start: () => {
      held = true;
    },
    change: () => {
      if (held) showTurning(true); // only once the camera actually moves: a click to pick stays full
    },
    end: () => {
      held = false;
      showTurning(false);
    },
  });

  function clear() {
    turning = false;
    root.dataset.turning = "false";
    if (!coarse) return;
    scene.remove(coarse);
    coarse.geometry.dispose();
    coarse = null;
  }

  return {
    draw,
    clear,
    dispose() {
      clear();
      unlisten();
    },
  };
}
