/**
 * The editor's autosave in IndexedDB: the scene, its undo history and the assets it names.
 * - Each history scene is one record, written once: a commit adds the new scene and rewrites the
 *   small timeline record (which record is the present, which are undo and redo steps), and
 *   deletes the records no step uses any more. Nothing is stringified or measured per commit.
 * - Assets (uploaded OBJ, glTF and image bytes) are kept once by id, shared by every history
 *   entry; scenes hold only their ids. Assets no kept scene names are deleted at start-up.
 * Every write answers whether it was kept, and why not (a full quota, storage disabled), so the
 * editor can say so; nothing here fails silently.
 */
import type { Scene } from '../model/types';
import { validateScene } from '../model/validate';

const DATABASE = 'ray-studio-editor';
const VERSION = 1;
const SCENES = 'scenes';
const ASSETS = 'assets';
const META = 'meta';
const TIMELINE_KEY = 'timeline';

/** The outcome of a write. */
export type Kept = { ok: true } | { ok: false; reason: string };

/**
 * An asset's bytes as kept in the browser: a Blob (an imported File: the browser stores it
 * without copying its bytes on the page's thread) or an ArrayBuffer.
 */
export interface StoredAsset {
  id: string;
  mediaType: string;
  bytes: Blob | ArrayBuffer;
}

/** The bytes of a kept asset as an ArrayBuffer. */
export function assetBuffer(asset: StoredAsset): Promise<ArrayBuffer> {
  return asset.bytes instanceof ArrayBuffer ? Promise.resolve(asset.bytes) : asset.bytes.arrayBuffer();
}

/** The scene, undo steps (oldest first) and redo steps (next first) found on start-up. */
export interface SavedTimeline {
  scene: Scene;
  past: Scene[];
  future: Scene[];
}

interface TimelineRecord {
  present: string;
  past: string[];
  future: string[];
}

/** The asset ids a scene names: mesh and glTF assets, image textures. */
export function assetIdsOf(scene: Scene): string[] {
  const ids = new Set<string>();
  for (const o of scene.objects) {
    if ((o.type === 'mesh' || o.type === 'gltf') && o.asset) ids.add(o.asset);
    const texture = o.material?.texture;
    if (texture?.type === 'image' && texture.asset) ids.add(texture.asset);
  }
  return [...ids];
}

/** A sentence for a failed write. */
function reasonOf(error: DOMException | Error | null | undefined): string {
  if (error?.name === 'QuotaExceededError') return 'the browser’s storage for this site is full';
  return error?.message ? `the browser refused to store it (${error.message})` : 'the browser refused to store it';
}

export class EditorDb {
  /** The record key of each scene written (scenes are immutable: a scene once written is never written again). */
  private readonly keys = new WeakMap<Scene, string>();
  /** The records this editor's history uses and knows to be written (another tab's are never deleted here). */
  private stored = new Set<string>();
  /** Keys are this editor's own (`tab:n`), so two tabs never write the same record. */
  private readonly tab = typeof crypto.randomUUID === 'function' ? crypto.randomUUID() : String(Math.random()).slice(2);
  private nextKey = 1;

  private constructor(private readonly db: IDBDatabase) {}

  /** Opens (creating or upgrading) the database; rejects with a sentence when it cannot. */
  static open(factory: IDBFactory): Promise<EditorDb> {
    return new Promise((resolve, reject) => {
      let request: IDBOpenDBRequest;
      try {
        request = factory.open(DATABASE, VERSION);
      } catch (error) {
        reject(new Error(reasonOf(error as Error)));
        return;
      }
      request.onupgradeneeded = () => {
        const db = request.result;
        if (!db.objectStoreNames.contains(SCENES)) db.createObjectStore(SCENES);
        if (!db.objectStoreNames.contains(ASSETS)) db.createObjectStore(ASSETS, { keyPath: 'id' });
        if (!db.objectStoreNames.contains(META)) db.createObjectStore(META);
      };
      request.onsuccess = () => {
        const db = request.result;
        db.onversionchange = () => db.close();
        resolve(new EditorDb(db));
      };
      request.onerror = () => reject(new Error(reasonOf(request.error)));
      request.onblocked = () => reject(new Error('another tab with an older editor holds the storage open'));
    });
  }

  /** The kept scene and its history, or null when nothing (readable) is kept. */
  async load(): Promise<SavedTimeline | null> {
    const tx = this.db.transaction([SCENES, META], 'readonly');
    const timeline = await request<TimelineRecord | undefined>(tx.objectStore(META).get(TIMELINE_KEY));
    const keys = (await request<IDBValidKey[]>(tx.objectStore(SCENES).getAllKeys())).map(String);
    const named = new Set(timeline ? [timeline.present, ...timeline.past, ...timeline.future] : []);
    this.stored = new Set(keys.filter((key) => named.has(key)));
    // records no kept history names (left by a tab closed mid-write, or by another tab's steps)
    const orphans = keys.filter((key) => !named.has(key));
    if (orphans.length > 0) await this.write([SCENES], (t) => orphans.forEach((key) => t.objectStore(SCENES).delete(key)));
    if (!timeline) return null;
    const read = async (key: string): Promise<Scene | null> => {
      const value = await request<unknown>(this.db.transaction(SCENES).objectStore(SCENES).get(key));
      const result = validateScene(value);
      if (!result.ok) return null;
      this.keys.set(result.scene, key);
      return result.scene;
    };
    const scene = await read(timeline.present);
    if (!scene) return null;
    const many = async (list: string[]) => (await Promise.all(list.map(read))).filter((s): s is Scene => s !== null);
    return { scene, past: await many(timeline.past), future: await many(timeline.future) };
  }

  /** Keeps the present scene and its history: writes the scenes not yet kept, the timeline, and drops what no step uses. */
  async saveTimeline(present: Scene, past: readonly Scene[], future: readonly Scene[]): Promise<Kept> {
    const fresh: [string, Scene][] = [];
    const freshKeys = new Set<string>();
    const keyOf = (scene: Scene) => {
      let key = this.keys.get(scene);
      if (key === undefined) {
        key = `${this.tab}:${this.nextKey++}`;
        this.keys.set(scene, key);
      }
      if (!this.stored.has(key) && !freshKeys.has(key)) {
        freshKeys.add(key);
        fresh.push([key, scene]);
      }
      return key;
    };
    const record: TimelineRecord = { present: keyOf(present), past: past.map(keyOf), future: future.map(keyOf) };
    const used = new Set([record.present, ...record.past, ...record.future]);
    const gone = [...this.stored].filter((key) => !used.has(key));
    const kept = await this.write([SCENES, META], (tx) => {
      const scenes = tx.objectStore(SCENES);
      for (const [key, scene] of fresh) scenes.put(scene, key);
      for (const key of gone) scenes.delete(key);
      tx.objectStore(META).put(record, TIMELINE_KEY);
    });
    if (kept.ok) this.stored = used;
    return kept;
  }

  /** Keeps an asset's bytes (once per id). */
  putAsset(asset: StoredAsset): Promise<Kept> {
    return this.write([ASSETS], (tx) => tx.objectStore(ASSETS).put(asset));
  }

  /** An asset's bytes, or null when not kept here. */
  async getAsset(id: string): Promise<StoredAsset | null> {
    const value = await request<StoredAsset | undefined>(this.db.transaction(ASSETS).objectStore(ASSETS).get(id));
    return value ?? null;
  }

  /** Deletes the assets none of `scenes` names; answers how many went. */
  async pruneAssets(scenes: readonly Scene[]): Promise<number> {
    const named = new Set(scenes.flatMap(assetIdsOf));
    const ids = await request<IDBValidKey[]>(this.db.transaction(ASSETS).objectStore(ASSETS).getAllKeys());
    const unused = ids.map(String).filter((id) => !named.has(id));
    if (unused.length > 0) await this.write([ASSETS], (tx) => unused.forEach((id) => tx.objectStore(ASSETS).delete(id)));
    return unused.length;
  }

  close(): void {
    this.db.close();
  }

  private write(stores: string[], body: (tx: IDBTransaction) => void): Promise<Kept> {
    return new Promise((resolve) => {
      let tx: IDBTransaction;
      try {
        tx = this.db.transaction(stores, 'readwrite');
        body(tx);
      } catch (error) {
        resolve({ ok: false, reason: reasonOf(error as Error) });
        return;
      }
      tx.oncomplete = () => resolve({ ok: true });
      tx.onabort = () => resolve({ ok: false, reason: reasonOf(tx.error) });
    });
  }
}

function request<T>(r: IDBRequest): Promise<T> {
  return new Promise((resolve, reject) => {
    r.onsuccess = () => resolve(r.result as T);
    r.onerror = () => reject(new Error(reasonOf(r.error)));
  });
}
