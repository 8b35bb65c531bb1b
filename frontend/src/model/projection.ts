/**
 * Pure mapping between the world and the two SVG plan views.
 *
 * - Top view: x to the right, z DOWN the screen (+z towards the viewer standing at +z, the
 *   usual plan view), seen from above; the hidden depth axis is y.
 * - Side view: x to the right, y UP (SVG y is flipped), seen from +z; the hidden axis is z.
 *
 * A view has a zoom (SVG pixels per metre) and a pan (the world point at the view's centre),
 * and an SVG of `width` x `height` pixels whose user units are pixels.
 */
import type { ResolvedObject, Vec3 } from './types';
import { cross, length, normalize, rotateXYZ, sub } from './vec';

export type ViewKind = 'top' | 'side';
export type Vec2 = [number, number];

/** Zoom, pan and pixel size of one view. */
export interface ViewTransform {
  /** SVG pixels per metre. */
  zoom: number;
  /** World (horizontal, vertical) coordinates of the view's centre. */
  pan: Vec2;
  width: number;
  height: number;
}

interface Axes {
  /** World axis index shown horizontally. */
  u: 0 | 1 | 2;
  /** World axis index shown vertically. */
  v: 0 | 1 | 2;
  /** The hidden axis. */
  depth: 0 | 1 | 2;
  /** SVG y per world v: +1 when v grows down the screen, -1 when it grows up. */
  down: 1 | -1;
  /** Names for labels. */
  names: [string, string];
}

export const VIEW_AXES: Record<ViewKind, Axes> = {
  top: { u: 0, v: 2, depth: 1, down: 1, names: ['x', 'z'] },
  side: { u: 0, v: 1, depth: 2, down: -1, names: ['x', 'y'] },
};

/** The world point's coordinates in the view's plane (horizontal, vertical). */
export function worldToPlane(kind: ViewKind, p: Vec3): Vec2 {
  const a = VIEW_AXES[kind];
  return [p[a.u], p[a.v]];
}

/** Plane coordinates (as {@link worldToPlane} gives them) to SVG pixels. */
export function planeToSvg(kind: ViewKind, t: ViewTransform, q: Vec2): Vec2 {
  const a = VIEW_AXES[kind];
  return [t.width / 2 + (q[0] - t.pan[0]) * t.zoom, t.height / 2 + a.down * (q[1] - t.pan[1]) * t.zoom];
}

/** SVG pixels to plane coordinates; the inverse of {@link planeToSvg}. */
export function svgToPlane(kind: ViewKind, t: ViewTransform, s: Vec2): Vec2 {
  const a = VIEW_AXES[kind];
  return [t.pan[0] + (s[0] - t.width / 2) / t.zoom, t.pan[1] + (a.down * (s[1] - t.height / 2)) / t.zoom];
}

export function worldToSvg(kind: ViewKind, t: ViewTransform, p: Vec3): Vec2 {
  return planeToSvg(kind, t, worldToPlane(kind, p));
}

/**
 * The world point under an SVG point. The view cannot see its depth axis, so that
 * coordinate is taken from `base` (e.g. the dragged object's own position).
 */
export function svgToWorld(kind: ViewKind, t: ViewTransform, s: Vec2, base: Vec3 = [0, 0, 0]): Vec3 {
  const a = VIEW_AXES[kind];
  const q = svgToPlane(kind, t, s);
  const p: Vec3 = [...base];
  p[a.u] = q[0];
  p[a.v] = q[1];
  return p;
}

/** Zooms by `factor` keeping the world point under the SVG point `s` where it is. */
export function zoomAbout(kind: ViewKind, t: ViewTransform, s: Vec2, factor: number, limits: Vec2 = [2, 5000]): { zoom: number; pan: Vec2 } {
  const zoom = Math.min(limits[1], Math.max(limits[0], t.zoom * factor));
  const before = svgToPlane(kind, t, s);
  const after = svgToPlane(kind, { ...t, zoom }, s);
  return { zoom, pan: [t.pan[0] + before[0] - after[0], t.pan[1] + before[1] - after[1]] };
}

/** The pan after the content was dragged by (dx, dy) SVG pixels. */
export function panBy(kind: ViewKind, t: ViewTransform, dx: number, dy: number): Vec2 {
  return [t.pan[0] - dx / t.zoom, t.pan[1] - (VIEW_AXES[kind].down * dy) / t.zoom];
}

/** Rounds the view's two visible coordinates of `p` to multiples of `step`. */
export function snapToGrid(kind: ViewKind, p: Vec3, step: number): Vec3 {
  const a = VIEW_AXES[kind];
  const out: Vec3 = [...p];
  for (const i of [a.u, a.v]) out[i] = round(Math.round(p[i] / step) * step);
  return out;
}

/** A round step about one SVG pixel long (0.01 m at 40 px/m), so drags give tidy numbers. */
export function pixelStep(zoom: number): number {
  return 10 ** Math.floor(Math.log10(1 / zoom));
}

/** Grid lines in view: plane coordinates of the vertical and horizontal lines, and their step. */
export function gridLines(kind: ViewKind, t: ViewTransform, step: number, minPixels = 12) {
  let s = step;
  for (const f of [2, 2.5, 2, 2, 2.5, 2, 2, 2.5, 2]) if (s * t.zoom < minPixels) s *= f;
  const lo = svgToPlane(kind, t, [0, 0]);
  const hi = svgToPlane(kind, t, [t.width, t.height]);
  const range = (a: number, b: number) => {
    const out: number[] = [];
    for (let k = Math.ceil(Math.min(a, b) / s); k * s <= Math.max(a, b) && out.length < 500; k++) out.push(round(k * s));
    return out;
  };
  return { step: s, us: range(lo[0], hi[0]), vs: range(lo[1], hi[1]) };
}

const round = (x: number) => Math.round(x * 1e9) / 1e9;

/** The camera's frame as the engine builds it: u right, v up, w backwards; null if degenerate. */
export function cameraFrame(position: Vec3, lookAt: Vec3, up: Vec3): { u: Vec3; v: Vec3; w: Vec3 } | null {
  const back = sub(position, lookAt);
  if (length(back) === 0 || length(up) === 0) return null;
  const w = normalize(back);
  const side = cross(up, w);
  if (length(side) <= 1e-9 * length(up)) return null;
  const u = normalize(side);
  return { u, v: cross(w, u), w };
}

/** Camera settings the cone needs (resolved: no missing fields). */
export interface ConeCamera {
  position: Vec3;
  lookAt: Vec3;
  up: Vec3;
  fov: number;
}

/** The four corners of the view frustum at `distance` along the view axis (world). */
export function frustumCorners(camera: ConeCamera, aspect: number, distance: number): Vec3[] {
  const frame = cameraFrame(camera.position, camera.lookAt, camera.up);
  if (!frame) return [];
  const th = Math.tan((camera.fov * Math.PI) / 360);
  const { u, v, w } = frame;
  return [[-1, -1], [1, -1], [1, 1], [-1, 1]].map(([sx, sy]) => {
    const d = [0, 1, 2].map((i) => -w[i] + sx * th * aspect * u[i] + sy * th * v[i]) as Vec3;
    return [0, 1, 2].map((i) => camera.position[i] + distance * d[i]) as Vec3;
  });
}

/**
 * The camera's view cone as seen in a view, in plane coordinates: the convex outline of the
 * camera position and the frustum's corners at the target's distance (a wedge when the view
 * sees the camera from the side, the frame's rectangle when it looks along the camera).
 */
export function cameraCone(kind: ViewKind, camera: ConeCamera, aspect: number, distance?: number): Vec2[] {
  const reach = distance ?? length(sub(camera.lookAt, camera.position));
  const corners = frustumCorners(camera, aspect, reach);
  if (corners.length === 0) return [];
  return convexHull([camera.position, ...corners].map((p) => worldToPlane(kind, p)));
}

/** The outline of a box as seen in a view (convex hull of its eight projected corners). */
export function boxFootprint(kind: ViewKind, center: Vec3, size: Vec3, rotationDegrees: Vec3): Vec2[] {
  const corners: Vec2[] = [];
  for (const sx of [-0.5, 0.5]) for (const sy of [-0.5, 0.5]) for (const sz of [-0.5, 0.5]) {
    const r = rotateXYZ([sx * size[0], sy * size[1], sz * size[2]], rotationDegrees);
    corners.push(worldToPlane(kind, [center[0] + r[0], center[1] + r[1], center[2] + r[2]]));
  }
  return convexHull(corners);
}

/** How a plane looks in a view: edge-on (a line) when its normal lies in the view's plane. */
export function planeInView(kind: ViewKind, point: Vec3, normal: Vec3) {
  const n = normalize(normal);
  const a = VIEW_AXES[kind];
  const n2: Vec2 = [n[a.u], n[a.v]];
  const edgeOn = Math.abs(n[a.depth]) < 1e-6;
  return { edgeOn, origin: worldToPlane(kind, point), normal: n2, along: [-n2[1], n2[0]] as Vec2 };
}

/** Convex hull (counter-clockwise, Andrew's monotone chain); duplicates removed. */
export function convexHull(points: Vec2[]): Vec2[] {
  const pts = [...points].sort((p, q) => p[0] - q[0] || p[1] - q[1]);
  if (pts.length < 3) return pts;
  const turn = (o: Vec2, a: Vec2, b: Vec2) => (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
  const eps = 1e-12;
  const half = (list: Vec2[]) => {
    const out: Vec2[] = [];
    for (const p of list) {
      while (out.length >= 2 && turn(out[out.length - 2], out[out.length - 1], p) <= eps) out.pop();
      out.push(p);
    }
    out.pop();
    return out;
  };
  return [...half(pts), ...half([...pts].reverse())];
}

/** The depth of a world point in a view (bigger is nearer the viewer), for drawing order. */
export function viewDepth(kind: ViewKind, p: Vec3): number {
  return kind === 'top' ? p[1] : p[2];
}

/** A resolved object's reference point: centre, a plane's point, a mesh's position. */
export function objectAnchor(object: ResolvedObject): Vec3 {
  if (object.type === 'plane') return object.point;
  if (object.type === 'mesh' || object.type === 'gltf') return object.position;
  return object.center;
}

/**
 * The rectangle a world-space box covers in a view, in SVG pixels (`x`, `y` its top-left corner),
 * whichever way the view's vertical axis runs.
 */
export function boundsToSvgRect(kind: ViewKind, t: ViewTransform, bounds: { min: Vec3; max: Vec3 }) {
  const a = worldToSvg(kind, t, bounds.min);
  const b = worldToSvg(kind, t, bounds.max);
  return { x: Math.min(a[0], b[0]), y: Math.min(a[1], b[1]), width: Math.abs(b[0] - a[0]), height: Math.abs(b[1] - a[1]) };
}
