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
});
