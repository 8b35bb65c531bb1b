import { describe, expect, it } from 'vitest';
import { budgetProblems, cameraProblems, lightProblems, sceneProblems } from './sceneRules';
import { schemaProblems } from './schemaRules';
import type { Scene } from './types';

describe('schemaProblems', () => {
  it('finds the value rules of the schema, with the server’s messages', () => {
    const scene: Scene = {
      image: { width: 8000, height: 0 },
      camera: { fov: 0, up: [0, 0, 0] },
      render: { samples: 2.5 },
      objects: [
        { type: 'sphere', radius: -1, material: { type: 'glass', ior: 0.5 } },
        { type: 'box', size: [1, 0, 1] },
        { type: 'mesh', obj: 'v 0 0 0', scale: 0 },
      ],
      lights: [{ type: 'point', intensity: -3 }],
    };
    expect(schemaProblems(scene)).toEqual([
      { path: 'image.width', message: 'must be less than or equal to 4096' },
      { path: 'image.height', message: 'must be greater than or equal to 1' },
      { path: 'camera.fov', message: 'must be greater than 0' },
      { path: 'camera.up', message: 'must not be a zero-length vector' },
      { path: 'render.samples', message: 'must be a whole number' },
      { path: 'objects[0].radius', message: 'must be greater than 0' },
      { path: 'objects[0].material.ior', message: 'must be greater than or equal to 1' },
      { path: 'objects[1].size[1]', message: 'must be greater than 0' },
      { path: 'objects[2].scale', message: 'must be greater than 0' },
      { path: 'lights[0].intensity', message: 'must be greater than or equal to 0' },
    ]);
  });

  it('finds nothing in a valid scene, and stops at the limits themselves', () => {
    expect(schemaProblems({ image: { width: 4096, height: 1 }, camera: { fov: 179.9 }, objects: [{ type: 'sphere', radius: 1e-9 }] })).toEqual([]);
    expect(schemaProblems({ camera: { fov: 180 }, objects: [] })).toEqual([{ path: 'camera.fov', message: 'must be less than 180' }]);
  });

  it('bounds every coordinate by the server’s 1e12 metres, in its words', () => {
    const scene: Scene = {
      camera: { position: [0, 0, 1e12], lookAt: [0, -2e12, 0] },
      lights: [{ type: 'point', position: [1e300, 0, 0] }],
      objects: [
        { type: 'sphere', center: [0, 0, -1e12] },
        { type: 'plane', point: [0, 1.5e12, 0] },
        { type: 'mesh', obj: 'v 0 0 0', position: [0, 0, -1e13] },
      ],
    };
    expect(schemaProblems(scene)).toEqual([
      { path: 'camera.lookAt[1]', message: 'must be greater than or equal to -1e12' },
      { path: 'lights[0].position[0]', message: 'must be less than or equal to 1e12' },
      { path: 'objects[1].point[1]', message: 'must be less than or equal to 1e12' },
      { path: 'objects[2].position[2]', message: 'must be greater than or equal to -1e12' },
    ]);
  });
});

describe('cameraProblems', () => {
  it('refuses a target on the camera and an up along the view, as the server words it', () => {
    expect(cameraProblems({ camera: { position: [1, 2, 3], lookAt: [1, 2, 3] }, objects: [] })).toEqual([
      { path: 'camera.lookAt', message: 'must differ from camera.position' },
    ]);
    expect(cameraProblems({ camera: { position: [0, 5, 0], lookAt: [0, 0, 0], up: [0, -2, 0] }, objects: [] })).toEqual([
      { path: 'camera.up', message: "is parallel to the view direction (lookAt - position); the camera's roll is undefined" },
    ]);
    expect(cameraProblems({ camera: { position: [0, 5, 0], lookAt: [0, 0, 0], up: [0, 0, -1] }, objects: [] })).toEqual([]);
    expect(cameraProblems({ objects: [] })).toEqual([]);
  });
});

describe('budgetProblems', () => {
  it('counts width x height x samples against the budget and names no configuration key', () => {
    const over = budgetProblems({ image: { width: 4096, height: 4096 }, render: { samples: 32 }, objects: [] });
    expect(over).toHaveLength(1);
    expect(over[0].path).toBe('render.samples');
    expect(over[0].message).toContain('4096 x 4096 pixels x 32 samples = 536,870,912 samples');
    expect(over[0].message).not.toMatch(/studio\./);
    expect(budgetProblems({ image: { width: 4096, height: 4096 }, render: { samples: 16 }, objects: [] })).toEqual([]);
  });
});

describe('sceneProblems', () => {
  it('gives one list, the schema’s rule first when both name a field', () => {
    const problems = sceneProblems({ camera: { position: [0, 0, 0], lookAt: [0, 0, 0], up: [0, 0, 0] }, objects: [] });
    expect(problems.map((p) => p.path)).toEqual(['camera.up', 'camera.lookAt']);
  });

  it('names a bad light field once, with the lights’ rules', () => {
    const problems = sceneProblems({ lights: [{ type: 'point', intensity: -1, radius: -1 }], objects: [] });
    expect(problems).toEqual([
      { path: 'lights[0].intensity', message: 'must be greater than or equal to 0' },
      { path: 'lights[0].radius', message: 'must be greater than or equal to 0' },
    ]);
  });
});

describe('lightProblems', () => {
  it('refuses a negative or non-finite radius, and takes 0 and any positive radius', () => {
    const lights = [-0.1, Number.NaN, Infinity, 0, 1e-6, 100].map((radius) => ({ type: 'point' as const, radius }));
    expect(lightProblems({ lights, objects: [] })).toEqual([
      { path: 'lights[0].radius', message: 'must be greater than or equal to 0' },
      { path: 'lights[1].radius', message: 'must be a finite number' },
      { path: 'lights[2].radius', message: 'must be a finite number' },
    ]);
    expect(lightProblems({ objects: [] })).toEqual([]); // the default light
  });

  it('refuses an area light’s width or height of 0 or less, and an aim on its own position', () => {
    expect(lightProblems({
      objects: [],
      lights: [
        { type: 'area', size: [0, 1] },
        { type: 'area', size: [2, -1], position: [1, 2, 3], lookAt: [1, 2, 3] },
        { type: 'area', position: [0, 0, 0] }, // the default aim is the origin
        { type: 'area', size: [1e-6, 1e3], position: [0, 0, 0], lookAt: [0, 0, 1e-9] },
      ],
    })).toEqual([
      { path: 'lights[0].size[0]', message: 'must be greater than 0' },
      { path: 'lights[1].size[1]', message: 'must be greater than 0' },
      { path: 'lights[1].lookAt', message: 'must differ from lights[1].position' },
      { path: 'lights[2].lookAt', message: 'must differ from lights[2].position' },
    ]);
  });
});
