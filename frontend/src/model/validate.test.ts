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

  it('checks a mesh as the server does: exactly one of obj, file and asset, a scale above 0, vectors of three numbers', () => {
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
      { path: 'objects[1]', message: 'a mesh needs its OBJ text in "obj", a "file" name or an "asset" id' },
      { path: 'objects[2]', message: 'give the mesh one of "obj", "file" and "asset", not more' },
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
        { type: 'area', size: [1, 1, 1], lookAt: [0, 0], twoSided: 'no', name: 7 },
        { type: 'area', size: [1, 'x'] },
      ],
    });
    expect(result.ok ? [] : result.errors).toEqual([
      { path: 'lights[0].radius', message: 'must be a finite number' },
      { path: 'lights[0].size', message: expect.stringMatching(/^is not a known field/) },
      { path: 'lights[1].size', message: 'must be a list of two numbers [width, height]' },
      { path: 'lights[1].lookAt', message: 'must be a list of three numbers [x, y, z]' },
      { path: 'lights[1].twoSided', message: 'must be true or false' },
      { path: 'lights[1].name', message: 'must be a string' },
      { path: 'lights[2].size[1]', message: 'must be a finite number' },
    ]);
  });

  it('reads issue 45\'s asset meshes, glTF models and textures, naming each bad field', () => {
    const id = `sha256-${'ab'.repeat(32)}`;
    const ok = validateScene({
      objects: [
        { type: 'mesh', asset: id, material: { type: 'chalk', texture: { type: 'checker', colors: ['#ffffff', '#000000'], size: 0.5 } } },
        { type: 'gltf', asset: id, position: [0, 1, 0], rotation: [0, 90, 0], scale: 2 },
        { type: 'plane', material: { type: 'plastic', texture: { type: 'image', asset: id, scale: [2, 2] } } },
      ],
    });
    expect(ok.ok ? [] : ok.errors).toEqual([]);
    const bad = validateScene({
      objects: [
        { type: 'mesh', asset: 'sha256-xyz' },
        { type: 'gltf', scale: 0, material: { type: 'chalk' } },
        { type: 'sphere', material: { type: 'chalk', texture: { type: 'checker', colors: ['#fff', '#000000'] } } },
        { type: 'sphere', material: { type: 'flat', texture: { type: 'image', asset: id, scale: [1, -1] } } },
        { type: 'sphere', material: { type: 'flat', texture: { type: 'marble' } } },
      ],
    });
    expect(bad.ok ? [] : bad.errors).toEqual([
      { path: 'objects[0].asset', message: 'must be an asset id, sha256- and 64 hex digits' },
      { path: 'objects[1].scale', message: 'must be a finite number greater than 0' },
      { path: 'objects[1].material', message: expect.stringMatching(/^is not a known field/) },
      { path: 'objects[1].asset', message: 'is required' },
      { path: 'objects[2].material.texture.colors[0]', message: 'must be a colour of the form #rrggbb' },
      { path: 'objects[3].material.texture.scale[1]', message: 'must be a finite number greater than 0' },
      { path: 'objects[4].material.texture.type', message: 'must be one of "checker", "image"' },
    ]);
  });
});
