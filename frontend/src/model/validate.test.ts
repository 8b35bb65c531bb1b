import { describe, expect, it } from 'vitest';
import { describeErrors, parseScene, validateScene } from './validate';

describe('validateScene', () => {
  it('accepts the minimal scene and returns it', () => {
    const result = parseScene('{ "objects": [ { "type": "sphere" } ] }');
    expect(result).toEqual({ ok: true, scene: { objects: [{ type: 'sphere' }] } });
  });

  it('names each bad field by its JSON path', () => {
    const result = validateScene({
      version: 1,
      colour: '#fff',
      camera: { position: [0, 1], fov: '50' },
      lights: [{ type: 'spot' }],
      objects: [
        { type: 'sphere', radius: 'big' },
        { type: 'cone' },
        { type: 'box', material: { type: 'mirror', ior: 1.5, color: 'red' } },
      ],
    });
    expect(result.ok).toBe(false);
    const paths = result.ok ? [] : result.errors.map((e) => e.path);
    expect(paths).toEqual([
      'colour',
      'camera.position',
      'camera.fov',
      'lights[0].type',
      'objects[0].radius',
      'objects[1].type',
      'objects[2].material.ior',
      'objects[2].material.color',
    ]);
  });

  it('requires objects, refuses newer versions, non-objects and bad JSON', () => {
    expect(validateScene({})).toMatchObject({ ok: false, errors: [{ path: 'objects' }] });
    expect(validateScene({ version: 2, objects: [] })).toMatchObject({ ok: false, errors: [{ path: 'version' }] });
    expect(validateScene([1])).toMatchObject({ ok: false });
    const bad = parseScene('{ "objects": [ }');
    expect(bad.ok).toBe(false);
    if (!bad.ok) expect(describeErrors(bad.errors)).toMatch(/not valid JSON/);
  });

  it('checks a mesh as the server does: exactly one of obj and file, a scale above 0, vectors of three numbers', () => {
    const ok = validateScene({ objects: [{ type: 'mesh', obj: 'v 0 0 0\n', position: [0, 1, 0], scale: 0.5, rotation: [0, 90, 0] }, { type: 'mesh', file: 'meshes/torus-knot.obj' }] });
    expect(ok.ok).toBe(true);
    const result = validateScene({
      objects: [
        { type: 'sphere' },
        { type: 'mesh' },
        { type: 'mesh', obj: 'v 0 0 0\n', file: 'a.obj' },
        { type: 'mesh', obj: 'v 0 0 0\n', scale: 0 },
        { type: 'mesh', file: 'a.obj', scale: -1, position: [0, 1], rotation: [0, 0, 'x'], center: [0, 0, 0] },
        { type: 'mesh', obj: 42 },
      ],
    });
    expect(result.ok ? [] : result.errors).toEqual([
      { path: 'objects[1]', message: 'a mesh needs its OBJ text in "obj" or a "file" name' },
      { path: 'objects[2]', message: 'give the mesh either "obj" or "file", not both' },
      { path: 'objects[3].scale', message: 'must be a finite number greater than 0' },
      { path: 'objects[4].scale', message: 'must be a finite number greater than 0' },
      { path: 'objects[4].position', message: 'must be a list of three numbers [x, y, z]' },
      { path: 'objects[4].rotation[2]', message: 'must be a finite number' },
      { path: 'objects[4].center', message: expect.stringMatching(/^is not a known field/) },
      { path: 'objects[5].obj', message: 'must be a string' },
    ]);
  });

  it('reads sphere and area lights: a radius, a size of two numbers, an aim, two-sided', () => {
    const ok = validateScene({
      objects: [],
      lights: [
        { type: 'point', radius: 0.5 },
        { type: 'area', position: [0, 3, 0], size: [2, 1], lookAt: [0, 0, 0], color: '#ffeedd', intensity: 2, falloff: true, twoSided: false },
      ],
    });
    expect(ok.ok).toBe(true);
    const result = validateScene({
      objects: [],
      lights: [
        { type: 'point', radius: 'big', size: [1, 1] },
        { type: 'area', size: [1, 1, 1], lookAt: [0, 0], twoSided: 'no', name: 'key' },
        { type: 'area', size: [1, 'x'] },
      ],
    });
    expect(result.ok ? [] : result.errors).toEqual([
      { path: 'lights[0].radius', message: 'must be a finite number' },
      { path: 'lights[0].size', message: expect.stringMatching(/^is not a known field/) },
      { path: 'lights[1].size', message: 'must be a list of two numbers [width, height]' },
      { path: 'lights[1].lookAt', message: 'must be a list of three numbers [x, y, z]' },
      { path: 'lights[1].twoSided', message: 'must be true or false' },
      { path: 'lights[1].name', message: expect.stringMatching(/^is not a known field/) },
      { path: 'lights[2].size[1]', message: 'must be a finite number' },
    ]);
  });
});
