/**
 * What the 3D view's move/rotate/scale handles (three.js TransformControls) do to an object, as
 * pure functions: the pose the handles start from, and the object after the handles moved to a new
 * pose. The handles sit on a stand-in whose position is the object's anchor, whose rotation is the
 * box's or mesh's own (identity for spheres and planes), and whose scale starts at 1 each drag.
 * Values are rounded as a person would type them: millimetres, tenths of a degree.
 */
import { resolveObject } from './defaults';
import { anchorField } from './edits';
import { objectAnchor } from './projection';
import type { SceneObject, Vec3 } from './types';
import { rotateXYZ } from './vec';
import { NO_MESHES, type MeshLookup } from './meshCache';
import { meshBounds } from './obj';

export type GizmoMode = 'translate' | 'rotate' | 'scale';

/** A stand-in's pose: position in metres, Euler angles in degrees (order XYZ), scale factors. */
export interface GizmoPose {
  position: Vec3;
  rotation: Vec3;
  scale: Vec3;
}

/** Which handles an object kind has (a sphere does not turn, a plane has no size). */
export function gizmoModes(object: SceneObject): GizmoMode[] {
  if (object.type === 'sphere') return ['translate', 'scale'];
  if (object.type === 'plane') return ['translate', 'rotate'];
  return ['translate', 'rotate', 'scale'];
}

/** Where the handles start for an object. */
export function gizmoPose(object: SceneObject): GizmoPose {
  const r = resolveObject(object);
  const rotation: Vec3 = r.type === 'box' || r.type === 'mesh' || r.type === 'gltf' ? [...r.rotation] : [0, 0, 0];
  return { position: objectAnchor(r), rotation, scale: [1, 1, 1] };
}

const round = (v: number, step: number) => {
  const r = Math.round(v / step) * step;
  return Number(r.toFixed(Math.max(0, -Math.floor(Math.log10(step)))) ) || 0;
};
/** A position rounded to a step (a millimetre, or the grid when snapping). */
export const roundVec = (v: Vec3, step: number): Vec3 => [round(v[0], step), round(v[1], step), round(v[2], step)];
/** The one factor of a uniform scale: the component that moved furthest from 1 (the handle dragged). */
export function uniformFactor(scale: Vec3): number {
  return scale.reduce((best, s) => (Math.abs(Math.log(Math.abs(s) || 1e-9)) > Math.abs(Math.log(Math.abs(best) || 1e-9)) ? s : best), 1);
}
/**
 * The most one scale drag multiplies or divides by. TransformControls' uniform handle divides by
 * the press's distance from the centre: pressed right on the centre, 60 pixels made a radius of 1
 * into 375 (measured in Chromium); ten times is more than any one gesture means.
 */
export const MAX_SCALE_STEP = 10;
const clampFactor = (f: number) => Math.min(MAX_SCALE_STEP, Math.max(1 / MAX_SCALE_STEP, Math.abs(f)));

/** Sizes stay positive: a handle dragged through zero leaves a millimetre. */
const positive = (v: number) => Math.max(0.001, round(Math.abs(v), 0.001));

/**
 * The object after its handles moved from {@link gizmoPose} to `pose`: the anchor follows the
 * position; a box's or mesh's rotation is the new rotation, a plane's normal turns with it; a
 * sphere's radius, a mesh's scale (uniform) and a box's size (per axis) grow with the scale.
 * `step` is the position's rounding (a millimetre, or the grid when snapping).
 */
export function applyGizmo(object: SceneObject, pose: GizmoPose, step = 0.001): SceneObject {
  const r = resolveObject(object);
  const next = { ...object } as SceneObject & Record<string, unknown>;
  next[anchorField(object.type)] = roundVec(pose.position, step);
  switch (r.type) {
    case 'sphere':
      next.radius = positive(r.radius * clampFactor(uniformFactor(pose.scale)));
      break;
    case 'box':
      next.rotation = roundVec(pose.rotation, 0.1);
      next.size = [0, 1, 2].map((k) => positive(r.size[k] * clampFactor(pose.scale[k]))) as Vec3;
      break;
    case 'mesh':
    case 'gltf':
      next.rotation = roundVec(pose.rotation, 0.1);
      next.scale = Number((r.scale * clampFactor(uniformFactor(pose.scale))).toPrecision(4));
      break;
    case 'plane':
      next.normal = roundVec(rotateXYZ(r.normal, pose.rotation), 0.0001);
      break;
  }
  // keep only the fields that changed, so an untouched default stays unwritten
  const before = gizmoPose(object);
  if (pose.scale.every((s) => s === 1)) {
    if (r.type === 'sphere') next.radius = object.type === 'sphere' ? object.radius : undefined;
    if (r.type === 'box') next.size = (object as { size?: Vec3 }).size;
    if (r.type === 'mesh' || r.type === 'gltf') next.scale = (object as { scale?: number }).scale;
  }
  if (pose.rotation.every((a, k) => a === before.rotation[k])) {
    if (r.type === 'box' || r.type === 'mesh' || r.type === 'gltf') next.rotation = (object as { rotation?: Vec3 }).rotation;
    if (r.type === 'plane') next.normal = (object as { normal?: Vec3 }).normal;
  }
  if (pose.position.every((p, k) => p === before.position[k])) next[anchorField(object.type)] = (object as unknown as Record<string, unknown>)[anchorField(object.type)];
  for (const key of Object.keys(next)) if (next[key] === undefined) delete next[key];
  return next;
}

/**
 * Where an orbit camera goes to frame a ball (centre, radius) with a vertical field of view, seen
 * from the direction it looks now: the whole ball fits with a 15% margin.
 */
export function frameBall(center: Vec3, radius: number, fovDegrees: number, from: Vec3): { position: Vec3; target: Vec3 } {
  const half = ((Math.min(fovDegrees, 170) / 2) * Math.PI) / 180;
  const distance = (1.15 * Math.max(radius, 1e-3)) / Math.sin(half);
  let d: Vec3 = [from[0] - center[0], from[1] - center[1], from[2] - center[2]];
  const l = Math.hypot(...d);
  d = l > 0 ? [d[0] / l, d[1] / l, d[2] / l] : [0, 0, 1];
  return { position: [center[0] + d[0] * distance, center[1] + d[1] * distance, center[2] + d[2] * distance], target: [...center] };
}

/** A ball around an object, for framing it: its own extent (a plane: 2 m about its point). */
export function objectBall(object: SceneObject, meshes: MeshLookup = NO_MESHES): { center: Vec3; radius: number } {
  const r = resolveObject(object);
  switch (r.type) {
    case 'sphere':
      return { center: r.center, radius: Math.abs(r.radius) };
    case 'box':
      return { center: r.center, radius: Math.hypot(...r.size) / 2 };
    case 'plane':
      return { center: r.point, radius: 2 };
    case 'mesh':
    case 'gltf': {
      const state = meshes(r as never);
      if (state.status !== 'ready') return { center: r.position, radius: 1 };
      const { min, max } = meshBounds(r, state.mesh);
      return { center: [0, 1, 2].map((k) => (min[k] + max[k]) / 2) as Vec3, radius: Math.hypot(max[0] - min[0], max[1] - min[1], max[2] - min[2]) / 2 };
    }
  }
}
