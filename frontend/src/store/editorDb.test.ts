import { IDBFactory, IDBObjectStore } from 'fake-indexeddb';
import { afterEach, describe, expect, it, vi } from 'vitest';
import type { Scene } from '../model/types';
import { assetIdsOf, EditorDb } from './editorDb';

const A = `sha256-${'a'.repeat(64)}`;
const B = `sha256-${'b'.repeat(64)}`;
const scene = (name: string, asset = A): Scene => ({ name, objects: [{ type: 'mesh', asset, position: [0, 1, 0] }] });

/** Counts the scene records the database holds. */
async function sceneCount(factory: IDBFactory): Promise<number> {
  const db = await new Promise<IDBDatabase>((resolve) => {
    const r = factory.open('ray-studio-editor');
    r.onsuccess = () => resolve(r.result);
  });
  const count = await new Promise<number>((resolve) => {
    const r = db.transaction('scenes').objectStore('scenes').count();
    r.onsuccess = () => resolve(r.result);
  });
  db.close();
  return count;
}

describe('EditorDb', () => {
  afterEach(() => vi.restoreAllMocks());

  it('keeps the scene with its undo and redo steps across a reopen', async () => {
    const factory = new IDBFactory();
    const db = await EditorDb.open(factory);
    expect(await db.load()).toBeNull();
    const [s1, s2, s3, s4] = ['one', 'two', 'three', 'four'].map((n) => scene(n));
    expect(await db.saveTimeline(s3, [s1, s2], [s4])).toEqual({ ok: true });
    db.close();
    const again = await EditorDb.open(factory);
    expect(await again.load()).toEqual({ scene: s3, past: [s1, s2], future: [s4] });
  });

  it('writes each scene once: a commit adds one record, and steps no history holds are deleted', async () => {
    const factory = new IDBFactory();
    const db = await EditorDb.open(factory);
    const put = vi.spyOn(IDBObjectStore.prototype, 'put');
    const history = Array.from({ length: 200 }, (_, i) => scene(`s${i}`));
    await db.saveTimeline(history[199], history.slice(0, 199), []);
    put.mockClear();
    const next = scene('next');
    await db.saveTimeline(next, history, []);
    // the new scene and the timeline record; none of the 200 older scenes again
    expect(put).toHaveBeenCalledTimes(2);
    expect(await sceneCount(factory)).toBe(201);
    // undo twice, then a new edit forgets the two redo steps
    const other = scene('other');
    await db.saveTimeline(history[198], history.slice(0, 198), [history[199], next]);
    await db.saveTimeline(other, history.slice(0, 199), []);
    expect(await sceneCount(factory)).toBe(200);
  });

  it('keeps an asset once by id, shared by every history step, and prunes those no step names', async () => {
    const db = await EditorDb.open(new IDBFactory());
    const bytes = new TextEncoder().encode('v 0 0 0\n').buffer;
    await db.putAsset({ id: A, mediaType: 'model/obj', bytes });
    await db.putAsset({ id: A, mediaType: 'model/obj', bytes });
    await db.putAsset({ id: B, mediaType: 'image/png', bytes: new ArrayBuffer(3) });
    expect(await db.pruneAssets([scene('x'), scene('y')])).toBe(1);
    const kept = await db.getAsset(A);
    expect(kept?.mediaType).toBe('model/obj');
    expect(new TextDecoder().decode(kept?.bytes as ArrayBuffer)).toBe('v 0 0 0\n');
    expect(await db.getAsset(B)).toBeNull();
  });

  it('answers why a write was not kept (a full quota), and writes the scene on the next save', async () => {
    const factory = new IDBFactory();
    const db = await EditorDb.open(factory);
    vi.spyOn(IDBObjectStore.prototype, 'put').mockImplementationOnce(() => {
      throw new DOMException('quota', 'QuotaExceededError');
    });
    const s = scene('big');
    expect(await db.saveTimeline(s, [], [])).toEqual({ ok: false, reason: 'the browser’s storage for this site is full' });
    expect(await db.saveTimeline(s, [], [])).toEqual({ ok: true });
    expect(await sceneCount(factory)).toBe(1);
  });

  it('says why it cannot open', async () => {
    const factory = { open: () => { throw new DOMException('denied', 'SecurityError'); } } as unknown as IDBFactory;
    await expect(EditorDb.open(factory)).rejects.toThrow('the browser refused to store it (denied)');
  });

  it('finds the asset ids a scene names: meshes, glTF models and image textures', () => {
    const s: Scene = {
      objects: [
        { type: 'mesh', asset: A },
        { type: 'gltf', asset: B },
        { type: 'sphere', material: { type: 'chalk', texture: { type: 'image', asset: A } } },
        { type: 'mesh', obj: 'v 0 0 0' },
      ],
    };
    expect(assetIdsOf(s)).toEqual([A, B]);
  });

  it('never lets two tabs write the same record, and drops records no kept history names on the next start', async () => {
    const factory = new IDBFactory();
    const [a, b] = [await EditorDb.open(factory), await EditorDb.open(factory)];
    await a.load();
    await b.load();
    const [sa, sb] = [scene('tab a'), scene('tab b')];
    await a.saveTimeline(sa, [], []);
    await b.saveTimeline(sb, [], []);
    expect(await sceneCount(factory)).toBe(2); // neither overwrote the other's record
    const again = await EditorDb.open(factory);
    expect(await again.load()).toEqual({ scene: sb, past: [], future: [] }); // the last written timeline
    expect(await sceneCount(factory)).toBe(1);
  });
});
