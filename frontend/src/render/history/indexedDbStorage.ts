/**
 * The render history in the browser's IndexedDB: one record a render, its image and thumbnail as
 * Blobs (localStorage holds strings of about 5 MB in all, less than two full-HD PNGs). Every failure
 * (no IndexedDB, private browsing, quota exceeded, an upgrade blocked by an old tab) ends in the
 * {@link HistoryStorage} contract's silent fallback, and every request has a bound.
 */
import { NO_STORAGE, type HistoryStorage, type StoredHistory } from './historyStorage';
import type { RenderRecord } from './renderRecord';
import { within } from './within';

const DATABASE = 'ray-studio-render-history';
const VERSION = 1;
const RENDERS = 'renders';
const META = 'meta';
const STAGE_KEY = 'stage';

/**
 * How long one request may take before the history goes on without it. Opening takes tens of
 * milliseconds; an upgrade blocked by another tab would wait until that tab closes.
 */
export const STORAGE_TIMEOUT_MS = 3000;

const NOTHING: StoredHistory = { records: [], stageId: null };

/** The storage over `factory` (the browser's `indexedDB`), or {@link NO_STORAGE} when there is none. */
export function indexedDbStorage(factory: IDBFactory | undefined = browserIndexedDb(), timeoutMs = STORAGE_TIMEOUT_MS): HistoryStorage {
  if (!factory) return NO_STORAGE;
  let database: Promise<IDBDatabase | null> | null = null;
  const open = () => (database ??= within(openDatabase(factory), timeoutMs, null));

  /** Runs `body` in one transaction; resolves with what its result reads once the transaction is complete. */
  async function transact<T>(stores: string[], mode: IDBTransactionMode, body: (tx: IDBTransaction) => () => T, fallback: T): Promise<T> {
    const db = await open();
    if (!db) return fallback;
    const done = new Promise<T>((resolve) => {
      try {
        const tx = db.transaction(stores, mode);
        const result = body(tx);
        tx.oncomplete = () => resolve(result());
        tx.onerror = () => resolve(fallback);
        tx.onabort = () => resolve(fallback);
      } catch {
        resolve(fallback);
      }
    });
    return within(done, timeoutMs, fallback);
  }

  const nothing = () => undefined;
  return {
    load: () =>
      transact([RENDERS, META], 'readonly', (tx) => {
        const all = tx.objectStore(RENDERS).getAll();
        const stage = tx.objectStore(META).get(STAGE_KEY);
        return () => ({ records: Array.isArray(all.result) ? all.result : [], stageId: typeof stage.result === 'string' ? stage.result : null });
      }, NOTHING),
    put: (record: RenderRecord) =>
      transact([RENDERS], 'readwrite', (tx) => {
        tx.objectStore(RENDERS).put(record);
        return nothing;
      }, undefined),
    remove: (ids) =>
      ids.length === 0
        ? Promise.resolve()
        : transact([RENDERS], 'readwrite', (tx) => {
            for (const id of ids) tx.objectStore(RENDERS).delete(id);
            return nothing;
          }, undefined),
    setStage: (id) =>
      transact([META], 'readwrite', (tx) => {
        tx.objectStore(META).put(id, STAGE_KEY);
        return nothing;
      }, undefined),
  };
}

function openDatabase(factory: IDBFactory): Promise<IDBDatabase | null> {
  return new Promise((resolve) => {
    let request: IDBOpenDBRequest;
    try {
      request = factory.open(DATABASE, VERSION);
    } catch {
      resolve(null); // e.g. a SecurityError where storage is disabled
      return;
    }
    request.onupgradeneeded = () => {
      const db = request.result;
      if (!db.objectStoreNames.contains(RENDERS)) db.createObjectStore(RENDERS, { keyPath: 'id' });
      if (!db.objectStoreNames.contains(META)) db.createObjectStore(META);
    };
    request.onsuccess = () => {
      const db = request.result;
      db.onversionchange = () => db.close(); // a newer editor in another tab may upgrade
      resolve(db);
    };
    request.onerror = () => resolve(null);
    request.onblocked = () => resolve(null);
  });
}

function browserIndexedDb(): IDBFactory | undefined {
  try {
    return typeof indexedDB === 'undefined' ? undefined : indexedDB;
  } catch {
    return undefined;
  }
}
