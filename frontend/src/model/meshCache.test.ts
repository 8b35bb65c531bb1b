import { describe, expect, it, vi } from 'vitest';
import { fetchMeshFile, type FetchFn } from '../api/client';
import { gridObj, TETRAHEDRON_OBJ } from '../test/meshes';
import { boxMesh, meshBounds, parseObj } from './obj';
import { MeshCache, type MeshState } from './meshCache';
import type { MeshObject } from './types';

const ready = (state: MeshState) => (state.status === 'ready' ? state.mesh : null);

describe('MeshCache', () => {
  it('parses inline OBJ once per distinct text, whatever else about the mesh changes', () => {
    const cache = new MeshCache();
    const mesh: MeshObject = { type: 'mesh', obj: TETRAHEDRON_OBJ, position: [0, 0, 0] };
    const first = ready(cache.get(mesh));
    expect(first?.triangleCount).toBe(4);
    // A drag step or a material change keeps the text: the same parse comes back.
    for (let i = 0; i < 50; i++) {
      const moved: MeshObject = { ...mesh, position: [i, 0, 0], scale: 1 + i };
      expect(ready(cache.get(moved))).toBe(first);
    }
    // An equal text that is another string (after a JSON round trip) too.
    const copy = JSON.parse(JSON.stringify(mesh)) as MeshObject;
    expect(ready(cache.get(copy))).toBe(first);
    expect(ready(cache.get({ ...mesh, obj: TETRAHEDRON_OBJ + '\n' }))).not.toBe(first);
  });

  it('keeps a bounded number of inline texts, the least recently used going first', () => {
    const cache = new MeshCache(2);
    const texts = ['v 0 0 0\n', 'v 1 0 0\n', 'v 2 0 0\n'];
    const a = cache.parseInline(texts[0]);
    cache.parseInline(texts[1]);
    expect(cache.parseInline(texts[0])).toBe(a); // now the most recent
    cache.parseInline(texts[2]); // evicts texts[1]
    expect(cache.parseInline(texts[0])).toBe(a);
  });

  it('reports a parse error with its line, and a mesh with neither or both sources', () => {
    const cache = new MeshCache();
    expect(cache.get({ type: 'mesh', obj: 'v 0 0 0\nf 1 2 3\n' })).toEqual({ status: 'error', message: 'line 2: index 2 out of range (1 vertex so far)' });
    expect(cache.get({ type: 'mesh' })).toMatchObject({ status: 'error', message: expect.stringContaining('needs') });
    expect(cache.get({ type: 'mesh', obj: '', file: 'a.obj' })).toMatchObject({ status: 'error', message: expect.stringContaining('not more') });
  });

  it('loads each file once, tells subscribers when it arrives, and keeps it', async () => {
    const cache = new MeshCache();
    const load = vi.fn(async () => TETRAHEDRON_OBJ);
    const listener = vi.fn();
    cache.subscribe(listener);
    const mesh: MeshObject = { type: 'mesh', file: 'meshes/tetra.obj' };
    expect(cache.get(mesh)).toEqual({ status: 'loading' });
    cache.ensure('meshes/tetra.obj', load);
    cache.ensure('meshes/tetra.obj', load);
    const before = cache.version();
    await vi.waitFor(() => expect(cache.get(mesh).status).toBe('ready'));
    expect(load).toHaveBeenCalledTimes(1);
    expect(listener).toHaveBeenCalledTimes(1);
    expect(cache.version()).not.toBe(before);
    cache.ensure('meshes/tetra.obj', load);
    expect(load).toHaveBeenCalledTimes(1);
    expect(ready(cache.get(mesh))?.triangleCount).toBe(4);
  });

  it('keeps a failed file as an error naming the file, from the server or from the OBJ', async () => {
    const cache = new MeshCache();
    const fetchFn = vi.fn<FetchFn>(async (url) =>
      url.endsWith('missing.obj')
        ? Response.json({ status: 404, title: 'Not Found', detail: "no mesh 'missing.obj' ships with this server" }, { status: 404, headers: { 'Content-Type': 'application/problem+json' } })
        : new Response('v 0 0 0\nf 1 1 7\n', { headers: { 'Content-Type': 'text/plain' } }),
    );
    cache.ensure('missing.obj', (f) => fetchMeshFile(f, fetchFn));
    cache.ensure('broken.obj', (f) => fetchMeshFile(f, fetchFn));
    await vi.waitFor(() => expect(cache.get({ type: 'mesh', file: 'broken.obj' }).status).toBe('error'));
    await vi.waitFor(() => expect(cache.get({ type: 'mesh', file: 'missing.obj' }).status).toBe('error'));
    expect(cache.get({ type: 'mesh', file: 'missing.obj' })).toEqual({ status: 'error', message: "missing.obj: Not Found: no mesh 'missing.obj' ships with this server" });
    expect(cache.get({ type: 'mesh', file: 'broken.obj' })).toEqual({ status: 'error', message: 'broken.obj: line 2: index 7 out of range (1 vertex so far)' });
  });

  it('forgets an answer that arrives after it was cleared', async () => {
    const cache = new MeshCache();
    let resolve: (text: string) => void = () => {};
    cache.ensure('late.obj', () => new Promise<string>((r) => (resolve = r)));
    cache.clear();
    resolve(TETRAHEDRON_OBJ);
    await Promise.resolve();
    await Promise.resolve();
    expect(cache.get({ type: 'mesh', file: 'late.obj' })).toEqual({ status: 'loading' });
  });

  it('reads an asset mesh once per id, in slices with its progress, and keeps what an import read', async () => {
    const cache = new MeshCache();
    const id = `sha256-${'e'.repeat(64)}`;
    const load = vi.fn(async () => gridObj(60));
    const seen: MeshState[] = [];
    cache.subscribe(() => seen.push(cache.get({ type: 'mesh', asset: id })));
    expect(cache.get({ type: 'mesh', asset: id })).toEqual({ status: 'loading' });
    cache.ensureAsset(id, load);
    cache.ensureAsset(id, load);
    await vi.waitFor(() => expect(cache.get({ type: 'mesh', asset: id }).status).toBe('ready'));
    expect(load).toHaveBeenCalledTimes(1);
    expect(ready(cache.get({ type: 'mesh', asset: id }))?.triangleCount).toBe(7200);
    expect(seen.at(-1)?.status).toBe('ready');
    const imported = parseObj(TETRAHEDRON_OBJ);
    cache.putAsset('sha256-other', imported);
    expect(ready(cache.get({ type: 'mesh', asset: 'sha256-other' }))).toBe(imported);
  });

  it('says why an asset cannot be had, and holds a glTF model’s box once the preview has read it', async () => {
    const cache = new MeshCache();
    cache.ensureAsset('sha256-gone', async () => {
      throw new Error('Not Found: no asset');
    });
    await vi.waitFor(() => expect(cache.get({ type: 'mesh', asset: 'sha256-gone' })).toEqual({ status: 'error', message: 'sha256-gone…: Not Found: no asset' }));
    expect(cache.get({ type: 'gltf', asset: 'sha256-m' })).toEqual({ status: 'loading' });
    expect(cache.hasModel('sha256-m')).toBe(false);
    const box = boxMesh({ min: [-1, 0, -1], max: [1, 2, 1] });
    cache.setModel('sha256-m', { status: 'ready', mesh: box });
    expect(ready(cache.get({ type: 'gltf', asset: 'sha256-m' }))).toBe(box);
    expect(meshBounds({ position: [0, 1, 0], scale: 2 }, box)).toEqual({ min: [-2, 1, -2], max: [2, 5, 2] });
  });
});
