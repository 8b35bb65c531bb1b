/** What a plan view should show to see the whole scene, and the zoom that fits it. */
import { areaLightCorners } from './areaLight';
import { resolveScene } from './defaults';
import { NO_MESHES, type MeshLookup } from './meshCache';
import { meshBounds } from './obj';
import { VIEW_AXES, type Vec2, type ViewKind } from './projection';
import { rotateXYZ } from './vec';
import type { Scene, Vec3 } from './types';

/**
 * Points that outline the scene: sphere and box extremes, plane points, the corners of meshes'
 * bounds (or their positions while their triangles are not known), lights (an area light's corners
 * and aim), camera and target.
 */
export function scenePoints(scene: Scene, meshes: MeshLookup = NO_MESHES): Vec3[] {
  const r = resolveScene(scene);
  const points: Vec3[] = [r.camera.position, r.camera.lookAt];
  for (const l of r.lights) points.push(...(l.type === 'area' ? [...areaLightCorners(l.position, l.size, l.lookAt), l.lookAt] : [l.position]));
  for (const o of r.objects) {
    if (o.type === 'plane') points.push(o.point);
    else if (o.type === 'mesh' || o.type === 'gltf') {
      const state = meshes(o);
      if (state.status !== 'ready') points.push(o.position);
      else {
        const { min, max } = meshBounds(o, state.mesh);
        for (const x of [min[0], max[0]]) for (const y of [min[1], max[1]]) for (const z of [min[2], max[2]]) points.push([x, y, z]);
      }
    } else if (o.type === 'sphere') {
      for (const s of [-1, 1]) for (let k = 0; k < 3; k++) {
        const p: Vec3 = [...o.center];
        p[k] += s * o.radius;
        points.push(p);
      }
    } else {
      for (const sx of [-0.5, 0.5]) for (const sy of [-0.5, 0.5]) for (const sz of [-0.5, 0.5]) {
        const d = rotateXYZ([sx * o.size[0], sy * o.size[1], sz * o.size[2]], o.rotation);
        points.push([o.center[0] + d[0], o.center[1] + d[1], o.center[2] + d[2]]);
      }
    }
  }
  return points;
}

/**
 * Zoom and pan for both plan views so every point shows with a margin. Both views get the
 * same zoom and the same x centre, so a thing sits straight above itself in the two views
 * (they are the same size in the layout).
 */
export function fitViews(points: Vec3[], width: number, height: number, margin = 36): Record<ViewKind, { zoom: number; pan: Vec2 }> {
  const range = (axis: number) => {
    const values = points.map((p) => p[axis]).filter(Number.isFinite);
    return values.length ? [Math.min(...values), Math.max(...values)] : [-1, 1];
  };
  const [x, y, z] = [range(0), range(1), range(2)];
  const span = (r: number[]) => Math.max(r[1] - r[0], 1e-6);
  const usableW = Math.max(20, width - 2 * margin);
  const usableH = Math.max(20, height - 2 * margin);
  const zoom = Math.min(usableW / span(x), usableH / span(z), usableH / span(y));
  const clamped = Math.min(2000, Math.max(0.01, zoom));
  const mid = (r: number[]) => (r[0] + r[1]) / 2;
  const pan = (kind: ViewKind): Vec2 => {
    const a = VIEW_AXES[kind];
    return [mid([x, y, z][a.u]), mid([x, y, z][a.v])];
  };
  return { top: { zoom: clamped, pan: pan('top') }, side: { zoom: clamped, pan: pan('side') } };
}
