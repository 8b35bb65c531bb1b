import { describe, expect, it } from 'vitest';
import { formatBytes, MAX_IMPORT_BYTES, planImport } from './importFiles';

describe('planImport', () => {
  it('imports each supported extension, in any case, with the media type the server takes', () => {
    expect(planImport('knot.OBJ', 10)).toEqual({ kind: 'obj', mediaType: 'model/obj' });
    expect(planImport('duck.glb', 10)).toEqual({ kind: 'gltf', mediaType: 'model/gltf-binary' });
    expect(planImport('box.gltf', 10)).toEqual({ kind: 'gltf', mediaType: 'model/gltf+json' });
    expect(planImport('wood.png', 10)).toEqual({ kind: 'image', mediaType: 'image/png' });
    expect(planImport('photo.jpeg', 10)).toEqual({ kind: 'image', mediaType: 'image/jpeg' });
  });

  it('says why it refuses another file, an empty one or one too large to read', () => {
    expect(planImport('scene.fbx', 10)).toEqual({ problem: 'Cannot import scene.fbx: only .obj, .glb, .gltf, .png and .jpg files can be imported.' });
    expect(planImport('README', 10)).toMatchObject({ problem: expect.stringContaining('only .obj') });
    expect(planImport('a.obj', 0)).toEqual({ problem: 'Cannot import a.obj: the file is empty.' });
    expect(planImport('big.glb', MAX_IMPORT_BYTES + 1)).toEqual({ problem: 'Cannot import big.glb: it is 256 MB, more than the 256 MB the editor reads.' });
  });

  it('writes sizes for people', () => {
    expect(formatBytes(900)).toBe('900 bytes');
    expect(formatBytes(1536)).toBe('1.5 KB');
    expect(formatBytes(16 * 1024 * 1024)).toBe('16 MB');
    expect(formatBytes(7.1 * 1024 * 1024)).toBe('7.1 MB');
  });
});
