import { describe, expect, it } from 'vitest';
import { fitViews, scenePoints } from './bounds';
import { worldToSvg } from './projection';
import { TETRAHEDRON_OBJ } from '../test/meshes';
import { MeshCache } from './meshCache';
import { STARTER_SCENE } from './starterScene';
import type { Scene } from './types';

describe('fitViews', () => {
  it('shows every point of the scene in both views, with the same zoom and x centre', () => {
    const points = scenePoints(STARTER_SCENE);
    const fit = fitViews(points, 500, 300, 20);
    expect(fit.top.zoom).toBe(fit.side.zoom);
    expect(fit.top.pan[0]).toBe(fit.side.pan[0]);
    for (const kind of ['top', 'side'] as const) {
      for (const p of points) {
        const [x, y] = worldToSvg(kind, { ...fit[kind], width: 500, height: 300 }, p);
        expect(x).toBeGreaterThanOrEqual(20 - 1e-9);
        expect(x).toBeLessThanOrEqual(480 + 1e-9);
        expect(y).toBeGreaterThanOrEqual(20 - 1e-9);
        expect(y).toBeLessThanOrEqual(280 + 1e-9);
      }
    }
  });

  it('includes sphere extremes, box corners, lights, camera and target', () => {
    const points = scenePoints({ lights: [], camera: { position: [0, 0, 9], lookAt: [0, 0, 0] }, objects: [{ type: 'sphere', center: [5, 0, 0], radius: 2 }, { type: 'box', center: [-5, 0, 0], size: [2, 2, 2], rotation: [0, 45, 0] }] });
    const xs = points.map((p) => p[0]);
    expect(Math.max(...xs)).toBe(7);
    expect(Math.min(...xs)).toBeCloseTo(-5 - Math.SQRT2);
  });

  it('includes the corners of a mesh’s bounds, or its position while its triangles are unknown', () => {
    const scene: Scene = { lights: [], camera: { position: [0, 0, 1], lookAt: [0, 0, 0] }, objects: [{ type: 'mesh', obj: TETRAHEDRON_OBJ, position: [10, 0, 0], scale: 3 }] };
    const cache = new MeshCache();
    const xs = scenePoints(scene, (m) => cache.get(m)).map((p) => p[0]);
    expect(Math.max(...xs)).toBe(13);
    expect(Math.max(...scenePoints(scene).map((p) => p[0]))).toBe(10);
  });
});
