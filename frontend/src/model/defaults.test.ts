import { describe, expect, it } from 'vitest';
import { exampleScenes } from '../test/scenes';
import { blankScene, imageAspect, MATERIAL_DEFAULTS, newAreaLight, newLight, newMesh, newObject, resolveLight, resolveMaterial, resolveScene, SAMPLE_MESH_OBJ } from './defaults';
import { parseObj } from './obj';
import { STARTER_SCENE } from './starterScene';
import type { Scene } from './types';

describe('resolveScene', () => {
  it('fills every default of docs/scene-format.md for the minimal scene', () => {
    const r = resolveScene({ name: 'minimal', objects: [{ type: 'sphere' }, { type: 'plane' }] });
    expect(r.version).toBe(1);
    expect(r.image).toEqual({ width: 800, height: 600, format: 'png', quality: 0.92 });
    expect(r.camera).toEqual({ position: [0, 2, 8], lookAt: [0, 0, 0], up: [0, 1, 0], fov: 50 });
    expect(r.background).toBe('#20232a');
    expect(r.ambient).toBe(0.08);
    expect(r.render).toEqual({ sampler: 'sobol', samples: 16, maxDepth: 6, seed: 0, adaptive: 0.05 });
    expect(r.lights).toEqual([{ type: 'point', position: [5, 8, 5], color: '#ffffff', intensity: 1, falloff: false, radius: 0 }]);
    expect(r.objects[0]).toEqual({ type: 'sphere', center: [0, 1, 0], radius: 1, material: { type: 'chalk', color: '#cccccc', diffuse: 0.9 } });
    expect(r.objects[1]).toMatchObject({ type: 'plane', point: [0, 0, 0], normal: [0, 1, 0] });
  });

  it('keeps what the scene says and an empty light list', () => {
    const scene: Scene = { lights: [], ambient: 0, image: { width: 10 }, objects: [{ type: 'box', size: [1, 2, 3] }] };
    const r = resolveScene(scene);
    expect(r.lights).toEqual([]);
    expect(r.ambient).toBe(0);
    expect(r.image.width).toBe(10);
    expect(r.image.height).toBe(600);
    expect(r.objects[0]).toMatchObject({ center: [0, 0.5, 0], size: [1, 2, 3], rotation: [0, 0, 0] });
    expect(scene).toEqual({ lights: [], ambient: 0, image: { width: 10 }, objects: [{ type: 'box', size: [1, 2, 3] }] });
  });

  it('does not share default vectors between scenes', () => {
    const a = resolveScene({ objects: [] });
    a.camera.position[0] = 99;
    expect(resolveScene({ objects: [] }).camera.position[0]).toBe(0);
  });

  it('resolves each material kind with only its own overrides', () => {
    expect(resolveMaterial({ type: 'glass', ior: 1.33 })).toEqual({ type: 'glass', color: '#ffffff', ior: 1.33, specular: 0.6, shininess: 250 });
    expect(resolveMaterial({ type: 'mirror' })).toEqual({ type: 'mirror', color: '#ffffff', reflectivity: 1 });
    expect(resolveMaterial({ type: 'metal' })).toEqual(MATERIAL_DEFAULTS.metal);
    expect(resolveMaterial(undefined)).toEqual({ type: 'chalk', color: '#cccccc', diffuse: 0.9 });
  });

  it('gives the image aspect, new objects and a blank scene', () => {
    expect(imageAspect({ image: { width: 1920, height: 1080 }, objects: [] })).toBeCloseTo(16 / 9);
    expect(newObject('box')).toMatchObject({ type: 'box', center: [0, 0.5, 0], size: [1, 1, 1], rotation: [0, 0, 0] });
    expect(blankScene().objects).toEqual([]);
  });

  it('resolves every example scene', () => {
    for (const [, json] of exampleScenes()) expect(() => resolveScene(json as Scene)).not.toThrow();
  });

  it('starts from a copy of scenes/still-life.json', () => {
    const stillLife = exampleScenes().find(([f]) => f === 'still-life.json')?.[1];
    expect(STARTER_SCENE).toEqual(stillLife);
  });

  it('resolves a mesh: origin, scale 1, no rotation, its source kept as it is', () => {
    const r = resolveScene({ objects: [{ type: 'mesh', file: 'meshes/torus-knot.obj' }, { type: 'mesh', obj: 'v 0 0 0\n', scale: 3 }] });
    expect(r.objects[0]).toEqual({ type: 'mesh', file: 'meshes/torus-knot.obj', position: [0, 0, 0], scale: 1, rotation: [0, 0, 0], material: { type: 'chalk', color: '#cccccc', diffuse: 0.9 } });
    expect(r.objects[1]).toMatchObject({ obj: 'v 0 0 0\n', scale: 3 });
    expect(r.objects[1]).not.toHaveProperty('file');
    expect(newObject('mesh')).toMatchObject({ type: 'mesh', obj: SAMPLE_MESH_OBJ, position: [0, 0, 0], scale: 1, rotation: [0, 0, 0] });
    expect(parseObj(SAMPLE_MESH_OBJ).triangleCount).toBe(8);
    expect(newMesh('v 0 0 0\n', 2.5)).toEqual({ type: 'mesh', obj: 'v 0 0 0\n', position: [0, 0, 0], scale: 2.5, rotation: [0, 0, 0], material: { type: 'plastic', color: '#4f8fd6' } });
  });

  it('resolves each kind of light with its own defaults', () => {
    expect(resolveLight({ type: 'point', radius: 0.25 })).toEqual({ type: 'point', position: [5, 8, 5], color: '#ffffff', intensity: 1, falloff: false, radius: 0.25 });
    expect(resolveLight({ type: 'area', size: [2, 0.5] })).toEqual({
      type: 'area', position: [5, 8, 5], size: [2, 0.5], lookAt: [0, 0, 0], color: '#ffffff', intensity: 1, falloff: false, twoSided: false,
    });
    const a = resolveLight({ type: 'area' });
    if (a.type === 'area') a.size[0] = 99;
    expect(resolveLight({ type: 'area' })).toMatchObject({ size: [1, 1] });
  });

  it('writes a new point light without a radius, and a new area light in full', () => {
    expect(newLight()).toEqual({ type: 'point', position: [5, 8, 5], color: '#ffffff', intensity: 1, falloff: false });
    expect(resolveScene({ objects: [] }).lights).toEqual([resolveLight(newLight())]);
    const area = newAreaLight([1, 2, 3], [0, 0, 0]);
    expect(area).toEqual({ type: 'area', position: [1, 2, 3], size: [1, 1], lookAt: [0, 0, 0], color: '#ffffff', intensity: 1, falloff: false, twoSided: false });
    area.size![0] = 5;
    expect(newAreaLight([1, 2, 3], [0, 0, 0]).size).toEqual([1, 1]);
  });
});
