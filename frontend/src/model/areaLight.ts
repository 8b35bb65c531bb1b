/**
 * Where an area light's rectangle lies (pure): the frame three.js gives a RectAreaLight that
 * `lookAt`s a point (Object3D.lookAt on a light, Matrix4.lookAt with up = +y), so the plan views,
 * the 3D preview and the render place and aim it alike. The rectangle is centred at the light's
 * position, `size[0]` wide along `right` and `size[1]` high along `up`; it emits along `front`,
 * towards `lookAt`.
 */
import { worldToPlane, type Vec2, type ViewKind } from './projection';
import type { Size2, Vec3 } from './types';
import { add, cross, normalize, scale, sub } from './vec';

/** The world up three.js's Object3D uses (Object3D.DEFAULT_UP). */
const WORLD_UP: Vec3 = [0, 1, 0];

/** Unit axes of an area light: its width along `right`, its height along `up`, its light along `front`. */
export interface AreaFrame {
  right: Vec3;
  up: Vec3;
  front: Vec3;
}

const lengthSq = (v: Vec3) => v[0] * v[0] + v[1] * v[1] + v[2] * v[2];

/**
 * The frame of a light at `position` aimed at `lookAt`, exactly as three.js's Matrix4.lookAt(eye,
 * target, up) builds it (its z axis points back, away from the target): looking straight down or
 * up, where up and the view are parallel, three nudges z by 1e-4 along world z, so the width lies
 * along x and the height along -z (looking down). A light on its target faces -z, as three's.
 */
export function areaLightFrame(position: Vec3, lookAt: Vec3): AreaFrame {
  let z = sub(position, lookAt);
  if (lengthSq(z) === 0) z = [0, 0, 1];
  z = normalize(z);
  let x = cross(WORLD_UP, z);
  if (lengthSq(x) === 0) {
    z = normalize([z[0], z[1], z[2] + 0.0001]);
    x = cross(WORLD_UP, z);
  }
  x = normalize(x);
  const y = cross(z, x);
  return { right: x, up: y, front: scale(z, -1) };
}

/** The rectangle's four corners in order around it: right-bottom, left-bottom, left-top, right-top. */
export function areaLightCorners(position: Vec3, size: Size2, lookAt: Vec3): [Vec3, Vec3, Vec3, Vec3] {
  const { right, up } = areaLightFrame(position, lookAt);
  const w = scale(right, size[0] / 2);
  const h = scale(up, size[1] / 2);
  const at = (sw: number, sh: number) => add(position, add(scale(w, sw), scale(h, sh)));
  return [at(1, -1), at(-1, -1), at(-1, 1), at(1, 1)];
}

/** What a plan view draws of an area light, in the view's plane coordinates (metres). */
export interface AreaLightOutline {
  /** The rectangle's corners as the view sees them (a line when it is seen edge-on). */
  corners: [Vec2, Vec2, Vec2, Vec2];
  /** The rectangle's centre. */
  centre: Vec2;
  /** The front's direction as the view sees it: unit length when it lies in the view's plane, 0 when it points along the view. */
  front: Vec2;
  /** The aim (lookAt). */
  aim: Vec2;
}

/** An area light seen from above (`top`) or the side: its rectangle, the way it faces and its aim. */
export function areaLightOutline(kind: ViewKind, position: Vec3, size: Size2, lookAt: Vec3): AreaLightOutline {
  const corners = areaLightCorners(position, size, lookAt).map((c) => worldToPlane(kind, c)) as AreaLightOutline['corners'];
  return {
    corners,
    centre: worldToPlane(kind, position),
    front: worldToPlane(kind, areaLightFrame(position, lookAt).front),
    aim: worldToPlane(kind, lookAt),
  };
}
