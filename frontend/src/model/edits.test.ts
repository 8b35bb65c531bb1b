import { describe, expect, it } from 'vitest';
import { addAreaLight, addLight, addMesh, aimLight, changeMaterialType, duplicateLight, duplicateObject, moveTarget, nudgeTarget, positionOf, setLightField, setMeshObj } from './edits';
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

  it('adds an area light above the camera target, a metre towards the camera, facing down onto the floor; each next one further along x', () => {
    const scene: Scene = { camera: { position: [1, 2, 7], lookAt: [1, 0.5, -1] }, objects: [{ type: 'plane', point: [0, 0.25, 0] }] };
    const one = addAreaLight(scene);
    expect(one.lights).toHaveLength(2); // the default light is written out beside it
    expect(one.lights![1]).toEqual({ type: 'area', name: 'Area light 2', position: [1, 3.5, 0], size: [1, 1], lookAt: [1, 0.25, 0], color: '#ffffff', intensity: 1, falloff: false, twoSided: false });
    const two = addAreaLight(addLight(one));
    expect(two.lights![3]).toMatchObject({ position: [3, 3.5, 0], lookAt: [3, 0.25, 0] });
    // its aim is never the camera's target, so both crosshairs can be grabbed in the plan views
    const above = addAreaLight({ camera: { position: [0, 9, 0], lookAt: [0, 0, 0] }, objects: [] });
    expect(above.lights![1]).toMatchObject({ position: [0, 3, 1], lookAt: [0, 0, 1] });
  });

  it('sets only the fields a light’s kind has', () => {
    const scene: Scene = { objects: [], lights: [{ type: 'point' }, { type: 'area' }] };
    expect(setLightField(scene, 0, 'radius', 0.3).lights![0]).toEqual({ type: 'point', radius: 0.3 });
    expect(setLightField(scene, 1, 'size', [2, 1]).lights![1]).toEqual({ type: 'area', size: [2, 1] });
    expect(setLightField(scene, 0, 'size', [2, 1])).toBe(scene);
    expect(setLightField(scene, 1, 'radius', 1)).toBe(scene);
    expect(setLightField(scene, 5, 'color', '#000000')).toBe(scene);
    expect(aimLight(scene, 1, [1, 2, 3]).lights![1]).toEqual({ type: 'area', lookAt: [1, 2, 3] });
    expect(aimLight(scene, 0, [1, 2, 3])).toBe(scene);
  });

  it('drags an area light’s aim as the camera target is dragged; a point light has none', () => {
    const scene: Scene = { objects: [], lights: [{ type: 'point' }, { type: 'area', position: [0, 2, 0] }] };
    expect(positionOf(scene, { kind: 'lightAim', index: 1 })).toEqual([0, 0, 0]);
    expect(positionOf(scene, { kind: 'lightAim', index: 0 })).toBeNull();
    expect(positionOf(scene, { kind: 'light', index: 1 })).toEqual([0, 2, 0]);
    expect(moveTarget(scene, { kind: 'lightAim', index: 1 }, [1, 0, 1]).lights![1]).toEqual({ type: 'area', position: [0, 2, 0], lookAt: [1, 0, 1] });
    expect(nudgeTarget(scene, { kind: 'light', index: 1 }, [0, 1, 0]).lights![1]).toEqual({ type: 'area', position: [0, 3, 0] });
  });

  it('duplicates an area light beside the original facing the same way', () => {
    const scene: Scene = { objects: [], lights: [{ type: 'area', position: [0, 2, 0], lookAt: [0, 0, 1], size: [2, 1] }] };
    expect(duplicateLight(scene, 0).lights![1]).toEqual({ type: 'area', position: [0.5, 2, 0.5], lookAt: [0.5, 0, 1.5], size: [2, 1] });
  });
});
