import { describe, expect, it } from 'vitest';
import { formatScene } from './formatScene';

describe('formatScene', () => {
  it('keeps vectors on one line and indents objects', () => {
    const text = formatScene({ camera: { position: [0, 2, 8], fov: 50 }, objects: [{ type: 'sphere' }] });
    expect(text).toBe(
      '{\n  "camera": {\n    "position": [0, 2, 8],\n    "fov": 50\n  },\n  "objects": [\n    {\n      "type": "sphere"\n    }\n  ]\n}',
    );
  });

  it('round-trips to the same value', () => {
    const scene = { name: 'a, b [c]', lights: [], objects: [{ center: [-1.5, 0, 1e-7], material: { color: '#ff0000' } }] };
    expect(JSON.parse(formatScene(scene))).toEqual(scene);
  });

  it('copies strings as they are, brackets and commas included, however long', () => {
    const obj = '# [ 1,2 ] {x}\nv 0 0 0\n'.repeat(20000) + 'f 1 1 1\n';
    const scene = { name: '[a,b]', objects: [{ type: 'mesh', obj, position: [0, 1, 0] }] };
    const text = formatScene(scene);
    expect(JSON.parse(text)).toEqual(scene);
    expect(text).toContain('"position": [0, 1, 0]');
  });
});
