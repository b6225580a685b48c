/*
 * The model's surface: one indexed mesh drawn in one pass, the side a face's normal points out
 * of in the "front" colour and the other side in "back".
 */
import { BufferAttribute, BufferGeometry, Color, DoubleSide, FrontSide, Mesh, MeshLambertMaterial } from "three";

/**
 * The surface's material: Lambert, both sides in one draw, the back side in its own colour
 * (gl_FrontFacing picks it per pixel), so the model's vertices and triangles go through the
 * pipeline once a frame rather than once per side. `side` becomes FrontSide to cull back faces.
 */
function twoSidedMaterial() {
  const material = new MeshLambertMaterial({ side: DoubleSide, flatShading: true, polygonOffset: true, polygonOffsetFactor: 1, polygonOffsetUnits: 1 });
  const backColor = { value: new Color() };
  material.onBeforeCompile = (shader) => {
    const line = "vec4 diffuseColor = vec4( diffuse, opacity );";
    if (!shader.fragmentShader.includes(line)) throw new Error("mesh view: three.js's Lambert shader changed");
    shader.uniforms.backDiffuse = backColor;
    shader.fragmentShader =
      "uniform vec3 backDiffuse;\n" + shader.fragmentShader.replace(line, "vec4 diffuseColor = vec4( gl_FrontFacing ? diffuse : backDiffuse, opacity );");
  };
  material.customProgramCacheKey = () => "trinormal-two-sided";
  return { material, backColor: backColor.value };
}

/**
 * scene -> { material, geometry(), mesh(), draw(pos, faces, vertexNormals), shade(cull, smooth),
 * setColors(front, back), clear(), dispose() }. pos: display positions (Float32, 3 per vertex);
 * faces: Uint32 (3 per face), kept in file order so a face's number is its place in the index.
 */
export function createSurface(scene) {
  const { material, backColor } = twoSidedMaterial();
  let geometry = null;
  let mesh = null;

  function draw(pos, faces, vertexNormals) {
    geometry = new BufferGeometry();
    geometry.setAttribute("position", new BufferAttribute(pos, 3));
    geometry.setIndex(new BufferAttribute(faces, 1));
    if (vertexNormals && vertexNormals.length === pos.length) {
      geometry.setAttribute("normal", new BufferAttribute(vertexNormals, 3));
    } // else three.js's own, made when smooth shading is first asked for (flat shading needs none)
    geometry.computeBoundingSphere();
    mesh = new Mesh(geometry, material);
    scene.add(mesh);
    return geometry;
  }

  /** Cull back faces or not; smooth shading (vertex normals) or one normal per face. */
  function shade(cull, smooth) {
    const side = cull ? FrontSide : DoubleSide;
    if (smooth && geometry && !geometry.getAttribute("normal")) geometry.computeVertexNormals();
    if (material.side !== side || material.flatShading === smooth) {
      material.side = side;
      material.flatShading = !smooth;
      material.needsUpdate = true;
    }
  }

  function clear() {
    if (mesh) scene.remove(mesh);
    if (geometry) geometry.dispose();
    geometry = mesh = null;
  }

  return {
    material,
    geometry: () => geometry,
    mesh: () => mesh,
    draw,
    shade,
    setColors(front, back) {
      material.color = new Color(front);
      backColor.set(back);
    },
    clear,
    dispose() {
      clear();
      material.dispose();
    },
  };
}
