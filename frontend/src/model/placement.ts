/**
 * Where a new object goes: on the floor, in front of the render camera, clear of the other
 * objects and of the camera target (whose crosshair would otherwise sit on the new object's
 * centre in the plan views, so that grabbing the object there moved the target instead). Pure.
 */
import { resolveScene } from './defaults';
import { NO_MESHES, type MeshLookup } from './meshCache';
import { meshBounds } from './obj';
import { cameraFrame } from './projection';
import type { Scene, Vec3 } from './types';
import { add, dot, length, normalize, scale, sub } from './vec';

/** Gap kept between a new object and anything it must be clear of, in metres. */
export const CLEARANCE = 0.25;

/** A footprint on the floor: a centre (x, z) and a radius that covers the object. */
interface Disc {
  x: number;
  z: number;
  r: number;
}

/**
 * The height of the floor: the highest horizontal plane (normal straight up) below the camera, or
 * y = 0 when the scene has none.
 */
export function floorHeight(scene: Scene): number {
  const r = resolveScene(scene);
  let floor: number | null = null;
  for (const o of r.objects) {
    if (o.type !== 'plane') continue;
    const n = normalize(o.normal);
    if (n[1] < 0.999 || o.point[1] > r.camera.position[1]) continue;
    floor = floor === null ? o.point[1] : Math.max(floor, o.point[1]);
  }
  return floor ?? 0;
}

/** The discs the objects of a scene cover on the floor (planes cover nothing one could stand beside). */
function footprints(scene: Scene, meshes: MeshLookup): Disc[] {
  const discs: Disc[] = [];
  for (const o of resolveScene(scene).objects) {
    if (o.type === 'sphere') discs.push({ x: o.center[0], z: o.center[2], r: Math.abs(o.radius) });
    else if (o.type === 'box') discs.push({ x: o.center[0], z: o.center[2], r: length(o.size) / 2 });
    else if (o.type === 'mesh' || o.type === 'gltf') {
      const state = meshes(o);
      if (state.status !== 'ready') discs.push({ x: o.position[0], z: o.position[2], r: 1 });
      else {
        const { min, max } = meshBounds(o, state.mesh);
        discs.push({ x: (min[0] + max[0]) / 2, z: (min[2] + max[2]) / 2, r: Math.hypot(max[0] - min[0], max[2] - min[2]) / 2 });
      }
    }
  }
  return discs;
}

/**
 * The centre of a new object of the given half-width (`radius`) and half-height (`halfHeight`),
 * standing on the floor: the first of a ring of spots around the camera target's floor point that
 * the camera sees (well inside the frame, in front of it), that overlaps no other object and
 * leaves the camera target clear in both plan views (top: x, z; side: x, y). Rounded to the
 * centimetre. When no spot qualifies, the one straight in front of the target's.
 */
export function placeOnFloor(scene: Scene, radius: number, halfHeight: number, meshes: MeshLookup = NO_MESHES): Vec3 {
  const r = resolveScene({ ...scene, objects: [] });
  const cam = r.camera;
  const floor = floorHeight(scene);
  const y = floor + halfHeight;
  const frame = cameraFrame(cam.position, cam.lookAt, cam.up);
  // Directions along the floor: "ahead" (away from the camera) and "right" as the camera sees them.
  let ahead = sub(cam.lookAt, cam.position);
  ahead = normalize([ahead[0], 0, ahead[2]]);
  if (length(ahead) === 0) ahead = [0, 0, -1];
  const right: Vec3 = [-ahead[2], 0, ahead[0]];
  // Where the camera looks, on the floor: the target's foot, or where the view ray meets the floor.
  const base: Vec3 = [cam.lookAt[0], floor, cam.lookAt[2]];
  const others = footprints(scene, meshes);
  const step = Math.max(2 * radius + CLEARANCE, 0.5);
  const target = cam.lookAt;
  const clear = (p: Vec3) =>
    others.every((d) => Math.hypot(p[0] - d.x, p[2] - d.z) >= d.r + radius + CLEARANCE) &&
    Math.hypot(p[0] - target[0], p[2] - target[2]) >= radius + CLEARANCE &&
    Math.hypot(p[0] - target[0], p[1] - target[1]) >= Math.max(radius, halfHeight) + CLEARANCE &&
    length(sub(p, cam.position)) > Math.max(radius, halfHeight) + CLEARANCE;
  const seen = (p: Vec3) => {
    if (!frame) return true;
    const d = sub(p, cam.position);
    const depth = -dot(d, frame.w);
    if (depth <= 0) return false;
    const tan = Math.tan(((cam.fov / 2) * Math.PI) / 180);
    const aspect = r.image.width / r.image.height;
    // well inside the frame (80%), centre and top of the object
    const inside = (q: Vec3) => {
      const e = sub(q, cam.position);
      const z = -dot(e, frame.w);
      return z > 0 && Math.abs(dot(e, frame.u)) <= 0.8 * z * tan * aspect && Math.abs(dot(e, frame.v)) <= 0.8 * z * tan;
    };
    return inside(p) && inside([p[0], p[1] + halfHeight, p[2]]);
  };
  const spots: { p: Vec3; cost: number }[] = [];
  for (let j = -4; j <= 8; j++) {
    for (let i = -8; i <= 8; i++) {
      const p = add(add(base, scale(right, i * step)), scale(ahead, j * step));
      p[1] = y;
      // nearest the target first; at equal distance, right before left and near before far
      spots.push({ p, cost: Math.hypot(i, j) + (i < 0 ? 0.01 : 0) + (j > 0 ? 0.02 : 0) });
    }
  }
  spots.sort((a, b) => a.cost - b.cost);
  const spot = spots.find(({ p }) => clear(p) && seen(p))?.p ?? [...add(base, scale(right, radius + CLEARANCE + 0.5))] as Vec3;
  return [centimetres(spot[0]), centimetres(y), centimetres(spot[2])];
}

const centimetres = (v: number) => Number((Math.round(v * 100) / 100).toFixed(2));
