import { describe, expect, it } from 'vitest';
import { applyGizmo, frameBall, gizmoModes, gizmoPose, objectBall, uniformFactor } from './gizmo';
import type { SceneObject, Vec3 } from './types';

const sphere: SceneObject = { type: 'sphere', center: [1, 1, 0], radius: 1, material: { type: 'chalk' } };
const box: SceneObject = { type: 'box', center: [0, 0.5, 0], size: [1, 2, 3], rotation: [0, 30, 0] };
const plane: SceneObject = { type: 'plane', point: [0, 0, 0], normal: [0, 1, 0] };
const mesh: SceneObject = { type: 'mesh', obj: 'v 0 0 0\n', position: [2, 0, 0], scale: 2 };

describe('3D handles (gizmo)', () => {
  it('starts at the anchor with the object’s own rotation and scale 1', () => {
    expect(gizmoPose(sphere)).toEqual({ position: [1, 1, 0], rotation: [0, 0, 0], scale: [1, 1, 1] });
    expect(gizmoPose(box)).toEqual({ position: [0, 0.5, 0], rotation: [0, 30, 0], scale: [1, 1, 1] });
    expect(gizmoModes(sphere)).toEqual(['translate', 'scale']);
    expect(gizmoModes(plane)).toEqual(['translate', 'rotate']);
  });

  it('moves only the anchor, rounded to the millimetre, leaving everything else as written', () => {
    const moved = applyGizmo(sphere, { ...gizmoPose(sphere), position: [1.23456, 1, -0.6000000000000001] });
    expect(moved).toEqual({ ...sphere, center: [1.235, 1, -0.6] });
    expect(applyGizmo({ type: 'box' }, { position: [1, 0.5, 0], rotation: [0, 0, 0], scale: [1, 1, 1] })).toEqual({ type: 'box', center: [1, 0.5, 0] });
    expect(applyGizmo(sphere, { ...gizmoPose(sphere), position: [1.3, 1, 0] }, 0.5)).toMatchObject({ center: [1.5, 1, 0] });
  });

  it('scales a sphere and a mesh uniformly, a box per axis; turns a box and a plane’s normal', () => {
    expect(applyGizmo(sphere, { ...gizmoPose(sphere), scale: [1, 1.5, 1] })).toMatchObject({ radius: 1.5 });
    expect(applyGizmo(mesh, { ...gizmoPose(mesh), scale: [0.5, 1, 1] })).toMatchObject({ scale: 1 });
    expect(applyGizmo(box, { ...gizmoPose(box), scale: [2, 1, 0.5] })).toMatchObject({ size: [2, 2, 1.5] });
    expect(applyGizmo(box, { ...gizmoPose(box), rotation: [0, 45.04, 0] })).toMatchObject({ rotation: [0, 45, 0] });
    const tilted = applyGizmo(plane, { ...gizmoPose(plane), rotation: [90, 0, 0] }) as { normal: Vec3 };
    expect(tilted.normal).toEqual([0, 0, 1]);
    // one drag scales by at most ten either way (a press on the very centre made 375)
    expect(applyGizmo(box, { ...gizmoPose(box), scale: [0, 1, 1] })).toMatchObject({ size: [0.1, 2, 3] });
    expect(applyGizmo(sphere, { ...gizmoPose(sphere), scale: [374.876, 374.876, 374.876] })).toMatchObject({ radius: 10 });
    expect(uniformFactor([1, 0.25, 1.5])).toBe(0.25);
  });

  it('frames a ball whole from the direction the camera looks, and knows each object’s ball', () => {
    const { position, target } = frameBall([1, 2, 3], 2, 50, [1, 2, 13]);
    expect(target).toEqual([1, 2, 3]);
    const distance = Math.hypot(position[0] - 1, position[1] - 2, position[2] - 3);
    expect(Math.asin(2 / distance)).toBeLessThan((25 * Math.PI) / 180); // the ball's silhouette fits in the half-angle
    expect(position[0]).toBeCloseTo(1, 9);
    expect(position[2]).toBeGreaterThan(3);
    expect(objectBall(sphere)).toEqual({ center: [1, 1, 0], radius: 1 });
    expect(objectBall(box).radius).toBeCloseTo(Math.hypot(1, 2, 3) / 2, 12);
  });
});
