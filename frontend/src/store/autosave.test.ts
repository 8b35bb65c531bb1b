import { IDBFactory, IDBObjectStore } from 'fake-indexeddb';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { assetIdOf } from '../model/assetHash';
import { STARTER_SCENE } from '../model/starterScene';
import { gridObj } from '../test/meshes';
import { autosaveSettled, keepAsset, keptAsset, startAutosave, useAutosaveStatus } from './autosave';
import { STORAGE_KEY } from './persistence';
import { resetSceneStore, useSceneStore } from './sceneStore';

const store = () => useSceneStore.getState();
let stop: () => void = () => undefined;

/** A reload: autosave stops, the page's store starts afresh, autosave starts over the same database. */
async function reload(factory: IDBFactory): Promise<void> {
  await autosaveSettled();
  stop();
  resetSceneStore();
  stop = await startAutosave(factory);
}

describe('autosave in IndexedDB', () => {
  afterEach(() => {
    stop();
    vi.restoreAllMocks();
  });

  it('brings back the scene and every edit, with undo and redo, after a reload', async () => {
    const factory = new IDBFactory();
    stop = await startAutosave(factory);
    store().setName('one');
    store().setName('two');
    store().setName('three');
    store().undo();
    await reload(factory);
    expect(store().scene.name).toBe('two');
    expect(store().past.map((s) => s.name)).toEqual(['still-life', 'one']);
    expect(store().future.map((s) => s.name)).toEqual(['three']);
    store().undo();
    expect(store().scene.name).toBe('one');
    await autosaveSettled();
    expect(useAutosaveStatus.getState()).toEqual({ state: 'saved' });
  });

  it('keeps a 200,000-triangle mesh, by its asset id, and each edit after it', async () => {
    const factory = new IDBFactory();
    stop = await startAutosave(factory);
    const obj = gridObj(317); // 200,978 triangles, 7.6 MB
    const bytes = new TextEncoder().encode(obj);
    const id = await assetIdOf(new Blob([bytes]));
    await keepAsset({ id, mediaType: 'model/obj', bytes: bytes.buffer });
    store().addModel({ type: 'mesh', asset: id, scale: 0.01 });
    store().moveObject(STARTER_SCENE.objects.length, [1, 0, 1]);
    store().setName('with a mesh');
    await reload(factory);
    expect(store().scene.name).toBe('with a mesh');
    expect(store().scene.objects.at(-1)).toMatchObject({ type: 'mesh', asset: id, position: [1, 0, 1] });
    expect(store().past).toHaveLength(3);
    const kept = await keptAsset(id);
    expect(new TextDecoder().decode(kept!.bytes as ArrayBuffer)).toBe(obj);
  });

  it('says when a change cannot be kept, and is back to keeping once the browser takes it', async () => {
    const factory = new IDBFactory();
    stop = await startAutosave(factory);
    vi.spyOn(IDBObjectStore.prototype, 'put').mockImplementationOnce(() => {
      throw new DOMException('quota', 'QuotaExceededError');
    });
    store().setName('too big');
    await autosaveSettled();
    expect(useAutosaveStatus.getState()).toEqual({
      state: 'failed',
      message: 'Your latest changes are not kept in this browser: the browser’s storage for this site is full. Use Save to download the scene.',
    });
    store().setName('smaller');
    await autosaveSettled();
    expect(useAutosaveStatus.getState()).toEqual({ state: 'saved' });
  });

  it('says so when the browser keeps nothing', async () => {
    stop = await startAutosave(undefined);
    expect(useAutosaveStatus.getState()).toMatchObject({ state: 'failed', message: expect.stringContaining('Use Save') });
    const refusing = { open: () => { throw new DOMException('denied', 'SecurityError'); } } as unknown as IDBFactory;
    stop = await startAutosave(refusing);
    expect(useAutosaveStatus.getState()).toMatchObject({ state: 'failed', message: expect.stringContaining('denied') });
  });

  it('takes over the scene an earlier editor kept in localStorage, once', async () => {
    localStorage.setItem(STORAGE_KEY, JSON.stringify({ name: 'from before', objects: [] }));
    const factory = new IDBFactory();
    stop = await startAutosave(factory);
    expect(store().scene.name).toBe('from before');
    await autosaveSettled();
    expect(localStorage.getItem(STORAGE_KEY)).toBeNull();
    await reload(factory);
    expect(store().scene.name).toBe('from before');
  });
});
