/**
 * Pure mapping of a scene onto what the three.js preview draws: plain descriptors (no three
 * objects, no React), plus the one helper that builds the render camera as a three.js
 * PerspectiveCamera. The preview component turns descriptors into meshes.
 */
import { PerspectiveCamera, Vector3 } from 'three';
import { resolveScene } from './defaults';
import { NO_MESHES, type MeshLookup } from './meshCache';
import { meshBounds, type ParsedObj } from './obj';
import { inItems, type SceneItem, type Selection } from './selection';
import { idOf } from './identity';
import type { Light, ResolvedLight, ResolvedMaterial, ResolvedObject, Scene, SceneObject, Texture, Vec3 } from './types';
import { cross, dot, length, normalize, sub } from './vec';

/**
 * three.js lights divide diffuse light by pi (physically based units); the engine does not.
 * Light and ambient intensities are multiplied by this so a chalk surface looks as bright.
 */
export const LIGHT_SCALE = Math.PI;

/**
 * How far the preview reaches, in distances from the camera to its target (10⁵: a scene of
 * metres seen from metres away reaches 100 km; the depth buffer keeps its precision).
 */
export const MAX_REACH = 1e5;

/**
 * How a material is approximated in the preview. `reflects`: the surface mirrors the scene around
 * it, so the preview gives it a cube map of the scene taken from where it stands (never a made-up
 * environment the render would not show).
 */
export type MaterialDescriptor = (
  | { kind: 'basic'; color: string }
  | { kind: 'lambert'; color: string; diffuse: number }
  | { kind: 'phong'; color: string; diffuse: number; specular: number; shininess: number }
  | { kind: 'standard'; color: string; metalness: number; roughness: number; reflects: true }
  | { kind: 'physical'; color: string; transmission: number; ior: number; roughness: number; reflects: true }
) & { texture?: TextureDescriptor };

/**
 * A material's texture as the preview maps it: a checker as a 2x2 texture of its colours (one
 * repeat is two squares), an image by its asset id; `repeat` and `offset` carry the surface's UVs
 * (a sphere's longitude and latitude, a box face's 0..1, a plane's quad) to the texture's units:
 * texture coordinate = uv · repeat + offset.
 */
export type TextureDescriptor =
  | { kind: 'checker'; colors: [string, string]; repeat: [number, number]; offset: [number, number] }
  | { kind: 'image'; asset: string; repeat: [number, number]; offset: [number, number] };

/**
 * The texture of a material on a surface whose UV unit spans `uvMetres` metres (1 for spheres and
 * box faces, whose UVs run 0..1 per face as the engine's do; a plane's quad side for planes), the
 * UV origin at `originMetres` in the texture's own units (a plane's quad is centred where the
 * camera is nearest, so its pattern is held in place by the offset).
 */
export function textureToThree(texture: Texture | undefined, uvMetres: [number, number] = [1, 1], originMetres: [number, number] = [0, 0]): TextureDescriptor | undefined {
  if (!texture) return undefined;
  if (texture.type === 'checker') {
    const period = 2 * (texture.size ?? 1);
    return { kind: 'checker', colors: texture.colors, repeat: [uvMetres[0] / period, uvMetres[1] / period], offset: [originMetres[0] / period, originMetres[1] / period] };
  }
  // an image named by a file beside the scene (the command line's) has no asset the preview could show
  if (texture.asset === undefined) return undefined;
  const [su, sv] = texture.scale ?? [1, 1];
  return { kind: 'image', asset: texture.asset, repeat: [su, sv], offset: [0, 0] };
}

export interface MeshDescriptor {
  /** The object's stable id in the editor (see {@link previewId}): the preview keeps its mesh by it. */
  id: string;
  /** Index of the scene object. */
  index: number;
  /**
   * Shared unit geometry: sphere radius 1, box edge 1, plane 1x1 in its x-y plane (normal +z); or
   * 'mesh': the triangles in `mesh`, in the OBJ's own coordinates (see `meshGeometry` in meshGeometry.ts).
   */
  geometry: 'sphere' | 'box' | 'plane' | 'mesh' | 'gltf';
  /**
   * The parsed OBJ of a 'mesh' (the same object for as long as the mesh's OBJ is unchanged); of a
   * 'gltf', its bounding box as 12 triangles (what a click picks; the model is drawn inside it).
   */
  mesh?: ParsedObj;
  /** The asset id of a 'gltf' model (the preview loads it and draws a copy of its scene). */
  asset?: string;
  position: Vec3;
  scale: Vec3;
  /** Euler angles in radians, order XYZ (boxes, meshes); planes use `quaternion` instead. */
  rotation: Vec3;
  /** [x, y, z, w]; identity except for planes. */
  quaternion: [number, number, number, number];
  material: MaterialDescriptor;
  selected: boolean;
}

interface LightCommon {
  /** The light's stable id in the editor (see {@link previewId}): the preview keeps its light by it. */
  id: string;
  index: number;
  position: Vec3;
  color: string;
  /** three.js intensity of a point (or spot) light: scene intensity times {@link LIGHT_SCALE}. */
  intensity: number;
  /** three.js decay: 0 without fall-off, 2 (inverse square) with. */
  decay: number;
  selected: boolean;
}

/** A point light; with a radius above 0 the preview shows its glowing sphere. */
export interface PointLightDescriptor extends LightCommon {
  kind: 'point';
  /** Metres; 0 for a point. */
  radius: number;
}

/**
 * An area light: a three.js RectAreaLight of `width` x `height` at `position` that looks at
 * `lookAt` (three.js's own frame, as `areaLightFrame`), of luminance `luminance`.
 */
export interface AreaLightDescriptor extends LightCommon {
  kind: 'area';
  width: number;
  height: number;
  lookAt: Vec3;
  /** RectAreaLight intensity (luminance); see {@link areaLuminance}. */
  luminance: number;
  twoSided: boolean;
}

export type LightDescriptor = PointLightDescriptor | AreaLightDescriptor;

export interface CameraDescriptor {
  position: Vec3;
  lookAt: Vec3;
  up: Vec3;
  /** Vertical field of view in degrees. */
  fov: number;
  /** Image width / height. */
  aspect: number;
  near: number;
  far: number;
}

export interface ThreeSceneDescriptor {
  background: string;
  /** three.js ambient intensity (scene ambient times {@link LIGHT_SCALE}). */
  ambient: number;
  camera: CameraDescriptor;
  meshes: MeshDescriptor[];
  lights: LightDescriptor[];
  /** A length that covers the scene seen from the camera (for far planes and plane quads). */
  extent: number;
}

/** Maps a material kind onto the closest three.js material. */
export function materialToThree(m: ResolvedMaterial, texture: TextureDescriptor | undefined = textureToThree(m.texture)): MaterialDescriptor {
  const d = untextured(m);
  return texture ? { ...d, texture } : d;
}

function untextured(m: ResolvedMaterial): MaterialDescriptor {
  switch (m.type) {
    case 'flat':
      return { kind: 'basic', color: m.color };
    case 'chalk':
      return { kind: 'lambert', color: m.color, diffuse: m.diffuse };
    case 'plastic':
      return { kind: 'phong', color: m.color, diffuse: m.diffuse, specular: m.specular, shininess: m.shininess };
    case 'metal':
      return { kind: 'standard', color: m.color, metalness: 0.5 + 0.5 * m.reflectivity, roughness: shininessToRoughness(m.shininess), reflects: true };
    case 'mirror':
      return { kind: 'standard', color: m.color, metalness: 1, roughness: 0, reflects: true };
    case 'glass':
      // refracts what is behind it (three.js transmission) and reflects its surroundings at grazing angles
      return { kind: 'physical', color: m.color, transmission: 1, ior: m.ior, roughness: 0, reflects: true };
  }
}

/** Blinn-Phong exponent to a GGX roughness (the usual sqrt(2 / (n + 2))). */
export function shininessToRoughness(shininess: number): number {
  return Math.min(1, Math.max(0.05, Math.sqrt(2 / (shininess + 2))));
}

/** `v` turned by the unit quaternion [x, y, z, w]. */
export function rotateByQuaternion(v: Vec3, [x, y, z, w]: [number, number, number, number]): Vec3 {
  // v + 2w (q × v) + 2 q × (q × v)
  const q: Vec3 = [x, y, z];
  const t = cross(q, v).map((c) => 2 * c) as Vec3;
  const u = cross(q, t);
  return [v[0] + w * t[0] + u[0], v[1] + w * t[1] + u[1], v[2] + w * t[2] + u[2]];
}

/** The quaternion [x, y, z, w] turning +z onto the direction of `normal`. */
export function quaternionFromZ(normal: Vec3): [number, number, number, number] {
  const n = normalize(normal);
  const d = n[2];
  if (d < -1 + 1e-12) return [1, 0, 0, 0];
  const axis = cross([0, 0, 1], n);
  const q: [number, number, number, number] = [axis[0], axis[1], axis[2], 1 + d];
  const l = Math.hypot(...q);
  return q.map((c) => c / l) as [number, number, number, number];
}

/**
 * The editor's id of an object or light (`object-2`, carried from edit to edit by the store), or
 * for one that has none (a scene that did not pass through the store, the default light of a
 * scene without lights) one made of its kind and index: `object@2`, which no editor id is.
 */
export function previewId(item: SceneObject | Light | undefined, kind: 'object' | 'light', index: number): string {
  return idOf(item) ?? `${kind}@${index}`;
}

function meshOf(o: ResolvedObject, id: string, index: number, selected: boolean, camera: Vec3, planeSize: number, meshes: MeshLookup): MeshDescriptor | null {
  const base = { id, index, selected, material: materialToThree(o.material), rotation: [0, 0, 0] as Vec3, quaternion: [0, 0, 0, 1] as [number, number, number, number] };
  switch (o.type) {
    case 'sphere':
      return { ...base, geometry: 'sphere', position: o.center, scale: [o.radius, o.radius, o.radius] };
    case 'box':
      return { ...base, geometry: 'box', position: o.center, scale: o.size, rotation: o.rotation.map(toRadians) as Vec3 };
    case 'plane': {
      // An infinite plane drawn as a large square centred where it is nearest the camera.
      const n = normalize(o.normal);
      const off = dot(sub(camera, o.point), n);
      const near: Vec3 = [camera[0] - off * n[0], camera[1] - off * n[1], camera[2] - off * n[2]];
      const size = planeSize;
      const quaternion = quaternionFromZ(o.normal);
      // the quad's own x and y axes in the world: the pattern is laid in metres along them, anchored at the world origin
      const ex = rotateByQuaternion([1, 0, 0], quaternion);
      const ey = rotateByQuaternion([0, 1, 0], quaternion);
      const origin: [number, number] = [dot(near, ex) - size / 2, dot(near, ey) - size / 2];
      const material = materialToThree(o.material, textureToThree(o.material.texture, [size, size], origin));
      return { ...base, material, geometry: 'plane', position: near, scale: [size, size, 1], quaternion };
    }
    case 'mesh': {
      // Drawn once its triangles are known; nothing while loading or broken (the inspector says why).
      const state = meshes(o);
      if (state.status !== 'ready') return null;
      const s = o.scale;
      return { ...base, geometry: 'mesh', mesh: state.mesh, position: o.position, scale: [s, s, s], rotation: o.rotation.map(toRadians) as Vec3 };
    }
    case 'gltf': {
      // Drawn once the preview has loaded the model (its box is then known); the glyph says why not.
      const state = meshes(o);
      if (state.status !== 'ready') return null;
      const s = o.scale;
      return { ...base, geometry: 'gltf', mesh: state.mesh, asset: o.asset, position: o.position, scale: [s, s, s], rotation: o.rotation.map(toRadians) as Vec3 };
    }
  }
}

/**
 * The side of the square an infinite plane is drawn as: its edges must lie outside everything the
 * camera sees up to the far plane, which at a wide field of view is far to the sides (at 179.9°
 * 1146 times the depth): a fixed size let the floor's edges show as a wedge.
 */
export function planeSize(far: number, fovDegrees: number, aspect: number): number {
  const tan = Math.tan((Math.min(Math.max(fovDegrees, 1), 179.99) / 2) * (Math.PI / 180));
  return 2 * far * (1 + tan * Math.max(1, aspect));
}

const toRadians = (d: number) => (d * Math.PI) / 180;

/**
 * The whole preview scene, with the selected objects and lights marked (the primary `selection`
 * and every one of a multi-selection, `items`). Meshes are drawn with the
 * triangles `meshes` knows (none by default); a mesh still loading or broken is left out.
 */
export function sceneToThree(scene: Scene, selection: Selection = null, meshes: MeshLookup = NO_MESHES, items: readonly SceneItem[] = []): ThreeSceneDescriptor {
  const isSelected = (kind: 'object' | 'light', index: number) => (selection?.kind === kind && selection.index === index) || inItems(items, { kind, index });
  const r = resolveScene(scene);
  const cam = r.camera;
  const targetDistance = Math.max(length(sub(cam.lookAt, cam.position)), 1e-9);
  // Anything further than this is left out of the preview (a dot at best in the render) and does
  // not stretch the depth range: one sphere at x = 1e300 made the far plane 4e300 and the floor
  // quad's corners Infinity as 32-bit floats, which blanked the whole picture, floor included.
  const horizon = MAX_REACH * targetDistance;
  const near = (p: Vec3, size = 0) => length(sub(p, cam.position)) + size <= horizon;
  let reach = targetDistance;
  const within = (d: number) => (d <= horizon ? Math.max(reach, d) : reach);
  for (const o of r.objects) {
    if (o.type === 'sphere') reach = within(length(sub(o.center, cam.position)) + Math.abs(o.radius));
    if (o.type === 'box') reach = within(length(sub(o.center, cam.position)) + length(o.size));
    if (o.type === 'mesh' || o.type === 'gltf') {
      const state = meshes(o);
      if (state.status === 'ready') {
        const { min, max } = meshBounds(o, state.mesh);
        const centre: Vec3 = [(min[0] + max[0]) / 2, (min[1] + max[1]) / 2, (min[2] + max[2]) / 2];
        reach = within(length(sub(centre, cam.position)) + length(sub(max, min)) / 2);
      } else reach = within(length(sub(o.position, cam.position)));
    }
  }
  for (const l of r.lights) reach = within(length(sub(l.position, cam.position)));
  const extent = reach * 2;
  const shown = (o: ResolvedObject) => {
    if (o.type === 'sphere') return near(o.center, Math.abs(o.radius));
    if (o.type === 'box') return near(o.center, length(o.size));
    if (o.type === 'mesh' || o.type === 'gltf') return near(o.position);
    // a plane far from the camera is drawn where it is nearest; one beyond the horizon is not
    return Math.abs(dot(sub(cam.position, o.point), normalize(o.normal))) <= horizon;
  };
  return {
    background: r.background,
    ambient: r.ambient * LIGHT_SCALE,
    camera: {
      position: cam.position,
      lookAt: cam.lookAt,
      up: cam.up,
      fov: cam.fov,
      aspect: r.image.width / r.image.height,
      // A wide lens sees things beside it at almost no depth: at 179.9 degrees the floor below the
      // camera is at 1/1000 of its distance in depth, and a near plane of 1/1000 of the target's
      // distance cut it away (the bottom of the picture was empty). The near plane shrinks with cos(fov / 2).
      near: (targetDistance / 1000) * Math.min(1, 2 * Math.cos((Math.min(cam.fov, 179.99) / 2) * (Math.PI / 180))),
      far: extent * 4,
    },
    meshes: r.objects.flatMap((o, i) => (shown(o) ? (meshOf(o, previewId(scene.objects[i], 'object', i), i, isSelected('object', i), cam.position, planeSize(extent * 4, cam.fov, r.image.width / r.image.height), meshes) ?? []) : [])),
    lights: r.lights.flatMap((l, i) => (near(l.position) ? lightOf(l, previewId(scene.lights?.[i], 'light', i), i, isSelected('light', i) || (selection?.kind === 'lightAim' && selection.index === i)) : [])),
    extent,
  };
}

/**
 * The RectAreaLight luminance that lights a surface facing it as the scene's light does. A small
 * rectangle of area A and luminance L gives E = L·A/d² at distance d on its axis, a point light of
 * three.js intensity I gives I/d² with fall-off (so L = I/A), and I everywhere without; a
 * RectAreaLight always falls off, so without fall-off it is matched at the distance of its aim.
 */
export function areaLuminance(intensity: number, width: number, height: number, falloff: boolean, aimDistance: number): number {
  const area = width * height;
  return ((intensity * LIGHT_SCALE) / area) * (falloff ? 1 : aimDistance * aimDistance);
}

/** The descriptor of a light, or none when the preview cannot draw it (an area light of no size or no aim). */
function lightOf(l: ResolvedLight, id: string, index: number, selected: boolean): LightDescriptor[] {
  const common = { id, index, position: l.position, color: l.color, intensity: l.intensity * LIGHT_SCALE, decay: l.falloff ? 2 : 0, selected };
  if (l.type === 'point') return [{ ...common, kind: 'point', radius: Number.isFinite(l.radius) && l.radius > 0 ? l.radius : 0 }];
  const [width, height] = l.size;
  const aimDistance = length(sub(l.lookAt, l.position));
  if (!(width > 0 && height > 0 && Number.isFinite(width * height) && aimDistance > 0)) return [];
  return [{ ...common, kind: 'area', width, height, lookAt: l.lookAt, luminance: areaLuminance(l.intensity, width, height, l.falloff, aimDistance), twoSided: l.twoSided }];
}

/** Puts a three.js PerspectiveCamera where the render camera is (position, up, lookAt, fov, aspect). */
export function applyRenderCamera(camera: PerspectiveCamera, d: CameraDescriptor): PerspectiveCamera {
  camera.fov = d.fov;
  camera.aspect = d.aspect;
  camera.near = d.near;
  camera.far = d.far;
  camera.zoom = 1;
  camera.position.set(...d.position);
  camera.up.set(...d.up);
  camera.lookAt(new Vector3(...d.lookAt));
  camera.updateProjectionMatrix();
  camera.updateMatrixWorld();
  return camera;
}

/** A new PerspectiveCamera framing exactly what the engine renders. */
export function makeRenderCamera(d: CameraDescriptor): PerspectiveCamera {
  return applyRenderCamera(new PerspectiveCamera(), d);
}

/**
 * Where a world point lands in the rendered image, in continuous pixel coordinates (the
 * centre of pixel (i, j) is (i + 0.5, j + 0.5)), via the three.js camera.
 */
export function projectToPixel(camera: PerspectiveCamera, point: Vec3, width: number, height: number): [number, number] {
  const ndc = new Vector3(...point).project(camera);
  return [((ndc.x + 1) / 2) * width, ((1 - ndc.y) / 2) * height];
}

/**
 * The largest box of the given aspect that fits a container, centred (letterboxing):
 * `{ width, height, left, top }` in the container's pixels.
 */
export function letterbox(containerWidth: number, containerHeight: number, aspect: number) {
  const width = Math.min(containerWidth, containerHeight * aspect);
  const height = width / aspect;
  return { width, height, left: (containerWidth - width) / 2, top: (containerHeight - height) / 2 };
}
