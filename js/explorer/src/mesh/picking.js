/*
 * Picking a face with the pointer: a click or a tap (the pointer lifted within a few pixels of
 * where it went down) casts a ray from the camera against a bounding volume hierarchy of the
 * faces (three-mesh-bvh), not against every face. The hierarchy is built once per model when
 * the page is next idle after the first picture, or at the first pick if that comes sooner.
 */
import { DoubleSide, FrontSide, Raycaster, Vector2 } from "three";
import { MeshBVH } from "three-mesh-bvh";
import { listen } from "../dom.js";

/** A click, not a drag: the pointer lifted within this many px of where it went down. */
const CLICK_PX = 4;

/**
 * { stage, surface, root, canPick, culled, frame, onPick } -> { schedule(), clear(), dispose() }.
 * Without canPick (a host that does not answer a picked face) a click picks nothing. culled()
 * says whether back faces are hidden (then they cannot be picked); frame() gives the display's
 * { offset, scale }, so that root's data-pick-point (where the ray met the face) is in the
 * model's own coordinates; onPick(face) receives each face clicked.
 */
export function createPicking({ stage, surface, root, canPick, culled, frame, onPick }) {
  const raycaster = new Raycaster();
  const ndc = new Vector2();
  let bvh = null;
  let cancel = null; // cancels the hierarchy's scheduled build
  let down = null;

  /** The faces' hierarchy; `indirect` keeps the index buffer (so face numbers) as the file has them. */
  function faceTree() {
    // leaves of about 32 faces rather than the default 10: a quicker build, and a pick still
    // tests only a few faces
    if (!bvh && surface.geometry()) bvh = new MeshBVH(surface.geometry(), { indirect: true, targetLeafSize: 32 });
    return bvh;
  }

  /** Build the hierarchy of the model just drawn when the page is next idle. */
  function schedule() {
    const idle = globalThis.requestIdleCallback || ((cb) => setTimeout(cb, 200));
    const cancelIdle = globalThis.cancelIdleCallback || clearTimeout;
    const id = idle(() => {
      cancel = null;
      faceTree();
    }, { timeout: 3000 });
    cancel = () => cancelIdle(id);
  }

  function facePicked(clientX, clientY) {
    if (!surface.mesh() || !faceTree()) return -1;
    const rect = stage.canvas.getBoundingClientRect();
    ndc.set(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    raycaster.setFromCamera(ndc, stage.camera);
    // the mesh is drawn untransformed: the world ray is the model's ray
    const hit = bvh.raycastFirst(raycaster.ray, culled() ? FrontSide : DoubleSide);
    if (!hit) return -1;
    // where the ray met the face, in the model's own coordinates (the tests check it is on it)
    const { offset, scale } = frame();
    root.dataset.pickPoint = hit.point.toArray().map((x, k) => x / scale + offset[k]).join(",");
    return hit.faceIndex;
  }

  function onDown(event) {
    down = event.button === 0 ? [event.clientX, event.clientY] : null;
  }
  function onUp(event) {
    if (!down || Math.hypot(event.clientX - down[0], event.clientY - down[1]) > CLICK_PX) return;
    down = null;
    if (!canPick) return;
    const face = facePicked(event.clientX, event.clientY);
    if (face >= 0) onPick(face);
  }
  const unlisten = listen(stage.canvas, { pointerdown: onDown, pointerup: onUp });

  function clear() {
    if (cancel) cancel();
    bvh = cancel = null;
  }

  return {
    schedule,
    clear,
    dispose() {
      clear();
      unlisten();
    },
  };
}
