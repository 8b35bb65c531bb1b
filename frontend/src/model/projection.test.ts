import { describe, expect, it } from 'vitest';
import {
  boundsToSvgRect,
  boxFootprint,
  cameraCone,
  convexHull,
  gridLines,
  panBy,
  planeInView,
  snapToGrid,
  svgToWorld,
  worldToSvg,
  zoomAbout,
  type ViewKind,
  type ViewTransform,
} from './projection';
import type { Vec3 } from './types';

/** A seeded pseudo-random generator, so failures repeat. */
function rng(seed: number) {
  let s = seed >>> 0;
  return () => {
    s = (s * 1664525 + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}

const KINDS: ViewKind[] = ['top', 'side'];

describe('projection', () => {
  it('svgToWorld(worldToSvg(p)) returns p within 1e-9 for random points and views', () => {
    const r = rng(42);
    for (let i = 0; i < 2000; i++) {
      const t: ViewTransform = { zoom: 0.5 + r() * 500, pan: [r() * 200 - 100, r() * 200 - 100], width: 100 + r() * 900, height: 100 + r() * 900 };
      const p: Vec3 = [r() * 200 - 100, r() * 200 - 100, r() * 200 - 100];
      for (const kind of KINDS) {
        const back = svgToWorld(kind, t, worldToSvg(kind, t, p), p);
        for (let k = 0; k < 3; k++) expect(Math.abs(back[k] - p[k])).toBeLessThan(1e-9);
      }
    }
  });

  it('top and side views agree on x', () => {
    const r = rng(7);
    for (let i = 0; i < 500; i++) {
      const t: ViewTransform = { zoom: 1 + r() * 100, pan: [r() * 10, r() * 10], width: 640, height: 480 };
      const p: Vec3 = [r() * 20 - 10, r() * 20 - 10, r() * 20 - 10];
      expect(worldToSvg('top', t, p)[0]).toBeCloseTo(worldToSvg('side', t, p)[0], 9);
    }
  });

  it('draws +z down the screen in the top view and +y up the screen in the side view', () => {
    const t: ViewTransform = { zoom: 10, pan: [0, 0], width: 200, height: 100 };
    expect(worldToSvg('top', t, [0, 0, 0])).toEqual([100, 50]);
    expect(worldToSvg('top', t, [1, 0, 2])).toEqual([110, 70]);
    expect(worldToSvg('side', t, [1, 2, 0])).toEqual([110, 30]);
    expect(worldToSvg('top', t, [0, 5, 0])).toEqual([100, 50]);
  });

  it('keeps the hidden coordinate from the base point', () => {
    const t: ViewTransform = { zoom: 10, pan: [0, 0], width: 200, height: 100 };
    expect(svgToWorld('top', t, [110, 70], [9, 3, 9])).toEqual([1, 3, 2]);
    expect(svgToWorld('side', t, [110, 30], [9, 9, -4])).toEqual([1, 2, -4]);
  });

  it('zooms about the cursor and pans with the pointer', () => {
    const t: ViewTransform = { zoom: 20, pan: [1, 2], width: 300, height: 200 };
    for (const kind of KINDS) {
      const under = svgToWorld(kind, t, [50, 60]);
      const zoomed = { ...t, ...zoomAbout(kind, t, [50, 60], 1.7) };
      expect(zoomed.zoom).toBeCloseTo(34);
      const still = svgToWorld(kind, zoomed, [50, 60]);
      for (let k = 0; k < 3; k++) expect(still[k]).toBeCloseTo(under[k], 9);
      const p: Vec3 = [0.3, 0.4, 0.5];
      const before = worldToSvg(kind, t, p);
      const after = worldToSvg(kind, { ...t, pan: panBy(kind, t, 15, -8) }, p);
      expect(after[0] - before[0]).toBeCloseTo(15, 9);
      expect(after[1] - before[1]).toBeCloseTo(-8, 9);
    }
  });

  it('snaps only the visible coordinates', () => {
    expect(snapToGrid('top', [0.26, 0.33, -0.74], 0.5)).toEqual([0.5, 0.33, -0.5]);
    expect(snapToGrid('side', [0.26, 0.33, -0.74], 0.5)).toEqual([0.5, 0.5, -0.74]);
  });

  it('lists grid lines in view, coarser when zoomed out', () => {
    const fine = gridLines('top', { zoom: 100, pan: [0, 0], width: 200, height: 100 }, 0.5);
    expect(fine.step).toBe(0.5);
    expect(fine.us).toEqual([-1, -0.5, 0, 0.5, 1]);
    const coarse = gridLines('top', { zoom: 2, pan: [0, 0], width: 200, height: 100 }, 0.5);
    expect(coarse.step * 2).toBeGreaterThanOrEqual(12);
  });
});

describe('view shapes', () => {
  it('outlines an unrotated box by its size, and a box turned 90° about y with x and z swapped', () => {
    const hull = boxFootprint('top', [0, 0, 0], [2, 1, 4], [0, 0, 0]);
    expect(hull).toHaveLength(4);
    const xs = hull.map((p) => p[0]);
    const zs = hull.map((p) => p[1]);
    expect([Math.min(...xs), Math.max(...xs), Math.min(...zs), Math.max(...zs)]).toEqual([-1, 1, -2, 2]);
    const turned = boxFootprint('top', [0, 0, 0], [2, 1, 4], [0, 90, 0]);
    expect(Math.max(...turned.map((p) => p[0]))).toBeCloseTo(2);
    expect(Math.max(...turned.map((p) => p[1]))).toBeCloseTo(1);
    const diamond = boxFootprint('top', [0, 0, 0], [1, 1, 1], [0, 45, 0]);
    expect(Math.max(...diamond.map((p) => p[0]))).toBeCloseTo(Math.SQRT1_2);
  });

  it('sees a floor edge-on from the side and face-on from above', () => {
    expect(planeInView('side', [0, 0, 0], [0, 1, 0]).edgeOn).toBe(true);
    expect(planeInView('top', [0, 0, 0], [0, 1, 0]).edgeOn).toBe(false);
    expect(planeInView('top', [0, 0, -3], [0, 0, 2]).edgeOn).toBe(true);
  });

  it('draws the view cone as a wedge whose half-angle is half the horizontal fov in the top view', () => {
    const camera = { position: [0, 0, 10] as Vec3, lookAt: [0, 0, 0] as Vec3, up: [0, 1, 0] as Vec3, fov: 60 };
    const cone = cameraCone('top', camera, 2, 10);
    expect(cone).toHaveLength(3);
    const halfWidth = Math.max(...cone.map((p) => p[0]));
    expect(halfWidth).toBeCloseTo(10 * Math.tan(Math.PI / 6) * 2, 9);
    const side = cameraCone('side', camera, 2, 10);
    expect(Math.max(...side.map((p) => p[1]))).toBeCloseTo(10 * Math.tan(Math.PI / 6), 9);
  });

  it('shows the frame rectangle when the camera looks straight down in the top view', () => {
    const camera = { position: [0, 10, 0] as Vec3, lookAt: [0, 0, 0] as Vec3, up: [0, 0, -1] as Vec3, fov: 90 };
    expect(cameraCone('top', camera, 1, 10)).toHaveLength(4);
  });

  it('computes a convex hull', () => {
    expect(convexHull([[0, 0], [1, 0], [1, 1], [0, 1], [0.5, 0.5]])).toHaveLength(4);
  });
});

describe('tidy drag positions', () => {
  it('rounds to about one pixel and removes float noise from grid snapping', async () => {
    const { pixelStep } = await import('./projection');
    expect(pixelStep(40)).toBe(0.01);
    expect(pixelStep(400)).toBe(0.001);
    expect(pixelStep(2)).toBe(0.1);
    expect(snapToGrid('top', [0.1 + 0.2, 0, 0.7], 0.1)).toEqual([0.3, 0, 0.7]);
  });

  it('maps a world box onto the same rectangle in x in both views, the side view flipped', () => {
    const t: ViewTransform = { zoom: 40, pan: [1, 2], width: 480, height: 320 };
    const bounds = { min: [-1, 0.5, 2] as Vec3, max: [3, 2.5, 5] as Vec3 };
    const top = boundsToSvgRect('top', t, bounds);
    const side = boundsToSvgRect('side', t, bounds);
    expect(top).toEqual({ x: 240 + (-1 - 1) * 40, y: 160 + (2 - 2) * 40, width: 160, height: 120 });
    expect(side).toEqual({ x: top.x, y: 160 - (2.5 - 2) * 40, width: 160, height: 80 });
  });
});
