import { describe, expect, it } from 'vitest';
import { addMesh, changeMaterialType, duplicateObject, moveTarget, nudgeTarget, positionOf, setMeshObj } from './edits';
import type { Scene } from './types';

const SCENE: Scene = {
  objects: [
    { type: 'sphere', center: [1, 1, 1] },
    { type: 'plane', point: [0, 0, 0], normal: [0, 2, 0] },
    { type: 'box' },
  ],
};

describe('edits', () => {
  it('duplicates beside the original, a plane along its normal', () => {
    expect(duplicateObject(SCENE, 0).objects[1]).toMatchObject({ center: [1.5, 1, 1.5] });
    expect(duplicateObject(SCENE, 1).objects[2]).toMatchObject({ point: [0, 0.5, 0] });
    expect(duplicateObject(SCENE, 2).objects[3]).toMatchObject({ center: [0.5, 0.5, 0.5] });
    expect(duplicateObject(SCENE, 9)).toBe(SCENE);
  });

  it('knows where every draggable thing is, defaults included, and moves it', () => {
    expect(positionOf(SCENE, { kind: 'object', index: 2 })).toEqual([0, 0.5, 0]);
    expect(positionOf(SCENE, { kind: 'light', index: 0 })).toEqual([5, 8, 5]);
    expect(positionOf(SCENE, { kind: 'camera' })).toEqual([0, 2, 8]);
    expect(positionOf(SCENE, { kind: 'target' })).toEqual([0, 0, 0]);
    expect(moveTarget(SCENE, { kind: 'object', index: 1 }, [0, -1, 0]).objects[1]).toMatchObject({ point: [0, -1, 0] });
    expect(nudgeTarget(SCENE, { kind: 'light', index: 0 }, [1, 0, 0]).lights).toEqual([{ type: 'point', position: [6, 8, 5], color: '#ffffff', intensity: 1, falloff: false }]);
  });

  it('changes a material kind keeping only what the new kind takes', () => {
    expect(changeMaterialType({ type: 'metal', color: '#111111', reflectivity: 0.2, shininess: 9, diffuse: 0.1 }, 'mirror')).toEqual({ type: 'mirror', reflectivity: 0.2 });
    expect(changeMaterialType({ type: 'metal', color: '#111111', reflectivity: 0.2, shininess: 9, diffuse: 0.1 }, 'plastic')).toEqual({ type: 'plastic', color: '#111111', shininess: 9, diffuse: 0.1 });
    expect(changeMaterialType(undefined, 'glass')).toEqual({ type: 'glass' });
  });

  it('moves, duplicates and re-sources a mesh by its position, changing nothing else', () => {
    const scene: Scene = { objects: [{ type: 'mesh', obj: 'v 0 0 0\n', scale: 2, rotation: [0, 30, 0], material: { type: 'mirror' } }] };
    expect(positionOf(scene, { kind: 'object', index: 0 })).toEqual([0, 0, 0]);
    const moved = moveTarget(scene, { kind: 'object', index: 0 }, [1, 2, 3]);
    expect(moved.objects[0]).toEqual({ ...scene.objects[0], position: [1, 2, 3] });
    expect(duplicateObject(moved, 0).objects[1]).toEqual({ ...moved.objects[0], position: [1.5, 2, 3.5] });
    const fromFile: Scene = { objects: [{ type: 'mesh', file: 'meshes/a.obj', scale: 2 }] };
    expect(setMeshObj(fromFile, 0, 'v 1 1 1\n').objects[0]).toEqual({ type: 'mesh', obj: 'v 1 1 1\n', scale: 2 });
    expect(setMeshObj(SCENE, 0, 'v 1 1 1\n')).toBe(SCENE); // not a mesh
    expect(addMesh(SCENE, 'v 0 0 0\n', 4).objects[3]).toMatchObject({ type: 'mesh', obj: 'v 0 0 0\n', scale: 4 });
    expect((addMesh(SCENE, 'v 0 0 0\n', 4).objects[3] as { position: number[] }).position[1]).toBe(0); // on the floor
  });
});
