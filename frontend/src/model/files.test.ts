import { describe, expect, it } from 'vitest';
import { sceneFileName, sceneFileText } from './files';

describe('scene files', () => {
  it('names the file after the scene, without paths, quotes or control characters', () => {
    expect(sceneFileName({ name: 'still-life', objects: [] })).toBe('still-life.json');
    expect(sceneFileName({ objects: [] })).toBe('render.json');
    expect(sceneFileName({ name: '../../etc/passwd', objects: [] })).toBe('etc-passwd.json');
    expect(sceneFileName({ name: 'a"b\n<c>', objects: [] })).toBe('abc.json');
    expect(sceneFileName({ name: '..', objects: [] })).toBe('render.json');
  });

  it('writes vectors on one line and reads back the same scene', () => {
    const scene = { name: 'x', camera: { position: [0, 2, 8] as [number, number, number] }, objects: [] };
    const text = sceneFileText(scene);
    expect(text).toContain('"position": [0, 2, 8]');
    expect(JSON.parse(text)).toEqual(scene);
  });
});
