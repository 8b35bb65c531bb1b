import { describe, expect, it, vi } from 'vitest';
import { ApiError } from '../api/client';
import { assetIdOf } from '../model/assetHash';
import { parseObjInChunks } from '../model/obj';
import type { Material, Scene } from '../model/types';
import { TETRAHEDRON_OBJ } from '../test/meshes';
import { importFile, ImportProblem, type ImportDeps, type ImportTarget } from './importFile';

const file = (text: string, name: string) => new File([text], name);

function fakes(onServer = false) {
  const calls: string[] = [];
  const deps: ImportDeps = {
    hash: async (blob, onProgress) => {
      calls.push('hash');
      onProgress(1);
      return assetIdOf(blob);
    },
    exists: async () => {
      calls.push('head');
      return onServer;
    },
    upload: async (blob, mediaType, onProgress) => {
      calls.push(`upload ${mediaType}`);
      onProgress(1);
      return { id: await assetIdOf(blob), bytes: blob.size, mediaType };
    },
    keep: async (asset) => void calls.push(`keep ${asset.mediaType}`),
    readObj: (text, onProgress) => parseObjInChunks(text, { onProgress }),
    readGltf: async () => ({ min: [-1, 0, -1], max: [1, 2, 1] }),
  };
  let scene: Scene = { objects: [{ type: 'sphere', material: { type: 'plastic', color: '#ff0000' } }, { type: 'gltf', asset: `sha256-${'c'.repeat(64)}` }] };
  const target: ImportTarget & { added: unknown[]; put: string[]; replaced: [number, string][] } = {
    added: [],
    put: [],
    replaced: [],
    scene: () => scene,
    selection: () => null,
    addModel: (model, bounds) => void target.added.push({ model, bounds }),
    setMaterial: (index: number, material: Material) => {
      scene = { ...scene, objects: scene.objects.map((o, i) => (i === index ? { ...o, material } : o)) as Scene['objects'] };
    },
    putMesh: (id) => void target.put.push(id),
    setMeshAsset: (index, id) => void target.replaced.push([index, id]),
  };
  return { deps, target, calls, scene: () => scene };
}

describe('importFile', () => {
  it('hashes, reads, uploads an OBJ the server lacks, keeps it, and adds it as a mesh by id', async () => {
    const { deps, target, calls } = fakes();
    const phases: string[] = [];
    const message = await importFile(file(TETRAHEDRON_OBJ, 'tetra.obj'), deps, target, (phase, f) => phases.push(`${phase} ${f}`));
    const id = await assetIdOf(new Blob([TETRAHEDRON_OBJ]));
    expect(calls).toEqual(['hash', 'head', 'upload model/obj', 'keep model/obj']);
    expect(phases).toEqual(['hashing 0', 'hashing 1', 'reading 0', 'reading 1', 'uploading 0', 'uploading 1']);
    expect(target.added).toEqual([{ model: { type: 'mesh', name: 'tetra', asset: id, scale: 2, material: { type: 'plastic', color: '#4f8fd6' } }, bounds: { min: [0, 0, 0], max: [1, 1, 1] } }]);
    expect(target.put).toEqual([id]);
    expect(message).toBe('tetra.obj: 4 triangles added as a mesh.');
  });

  it('replaces a mesh’s triangles by an OBJ, uploaded and read as any import, and takes nothing but an OBJ for that', async () => {
    const { deps, target, calls } = fakes();
    const message = await importFile(file(TETRAHEDRON_OBJ, 'tetra.obj'), deps, target, () => undefined, { replaceMesh: 3 });
    const id = await assetIdOf(new Blob([TETRAHEDRON_OBJ]));
    expect(calls).toEqual(['hash', 'head', 'upload model/obj', 'keep model/obj']);
    expect(target.replaced).toEqual([[3, id]]);
    expect(target.added).toEqual([]);
    expect(target.put).toEqual([id]);
    expect(message).toBe('tetra.obj: 4 triangles now make the mesh.');
    await expect(importFile(file('glb bytes', 'duck.glb'), deps, target, () => undefined, { replaceMesh: 3 })).rejects.toThrow(
      'Cannot use duck.glb as a mesh’s triangles: choose a Wavefront .obj file.'.replace('’', "'"),
    );
  });

  it('does not upload what the server has already', async () => {
    const { deps, target, calls } = fakes(true);
    await importFile(file('glb bytes', 'duck.glb'), deps, target, () => undefined);
    expect(calls).toEqual(['hash', 'head', 'keep model/gltf-binary']);
    expect(target.added).toEqual([{ model: { type: 'gltf', name: 'duck', asset: expect.stringMatching(/^sha256-/) }, bounds: { min: [-1, 0, -1], max: [1, 2, 1] } }]);
  });

  it('puts an image on the selected object’s material as its texture, and says an object must be selected', async () => {
    const { deps, target, calls, scene } = fakes();
    await expect(importFile(file('png', 'wood.png'), deps, target, () => undefined)).rejects.toThrow(
      'Cannot use wood.png as a texture: select the object whose material it should cover first, then drop or import the image again.',
    );
    target.selection = () => ({ kind: 'object', index: 1 });
    await expect(importFile(file('png', 'wood.png'), deps, target, () => undefined)).rejects.toThrow(/a glTF model brings its own materials/);
    expect(calls).toEqual([]);
    target.selection = () => ({ kind: 'object', index: 0 });
    await importFile(file('png', 'wood.png'), deps, target, () => undefined);
    expect(scene().objects[0].material).toEqual({ type: 'plastic', color: '#ff0000', texture: { type: 'image', asset: await assetIdOf(new Blob(['png'])), scale: [1, 1] } });
  });

  it('shows the server’s problem, a bad OBJ’s line and an unsupported file, and adds nothing', async () => {
    const { deps, target } = fakes();
    deps.upload = async () => {
      throw new ApiError(413, 'Payload Too Large', 'an asset may have at most 16777216 bytes');
    };
    await expect(importFile(file(TETRAHEDRON_OBJ, 'big.obj'), deps, target, () => undefined)).rejects.toThrow(
      new ImportProblem('Cannot import big.obj: the server refused it (Payload Too Large: an asset may have at most 16777216 bytes).'),
    );
    await expect(importFile(file('v 0 0 0\nf 1 2 3\n', 'bad.obj'), deps, target, () => undefined)).rejects.toThrow(
      'Cannot import bad.obj: it is not a usable OBJ mesh (line 2: index 2 out of range (1 vertex so far)).',
    );
    deps.readGltf = async () => {
      throw new Error('not a glTF 2.0 model this editor can read (Unexpected token)');
    };
    await expect(importFile(file('{', 'broken.gltf'), deps, target, () => undefined)).rejects.toThrow('Cannot import broken.gltf: not a glTF 2.0 model');
    await expect(importFile(file('x', 'scene.blend'), deps, target, () => undefined)).rejects.toThrow(/only \.obj, \.glb, \.gltf, \.png and \.jpg/);
    expect(target.added).toEqual([]);
  });

  it('refuses bytes the server names differently from the editor', async () => {
    const { deps, target } = fakes();
    const keep = vi.fn(deps.keep);
    deps.keep = keep;
    deps.upload = async (_blob, mediaType) => ({ id: `sha256-${'0'.repeat(64)}`, bytes: 1, mediaType });
    await expect(importFile(file(TETRAHEDRON_OBJ, 'a.obj'), deps, target, () => undefined)).rejects.toThrow(/the server named it sha256-0000/);
    expect(keep).not.toHaveBeenCalled();
  });
});
