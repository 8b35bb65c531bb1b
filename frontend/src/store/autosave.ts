/**
 * Autosave: every committed scene and the undo history go to IndexedDB ({@link EditorDb}), with
 * the bytes of every asset they name, so a reload finds the scene, each edit and each mesh again.
 * Whether that is working is itself state ({@link useAutosaveStatus}): when the browser refuses a
 * write (its quota is full, storage is disabled) the editor says so and offers Save; it never stops
 * keeping the scene without a word.
 */
import { create } from 'zustand';
import { carryIds } from '../model/identity';
import type { Scene } from '../model/types';
import { EditorDb, type StoredAsset } from './editorDb';
import { forgetLegacyScene, loadLegacyScene } from './persistence';
import { useSceneStore } from './sceneStore';

/** What autosave is doing: keeping everything, or not, and why not. */
export type AutosaveStatus =
  | { state: 'starting' }
  | { state: 'saved' }
  | { state: 'failed'; message: string };

export const useAutosaveStatus = create<AutosaveStatus>()(() => ({ state: 'starting' }));

/** How long start-up waits for the database before the editor opens without it (and says so). */
export const OPEN_TIMEOUT_MS = 3000;

let database: EditorDb | null = null;

const fail = (message: string) => useAutosaveStatus.setState({ state: 'failed', message }, true);

/** Puts a kept timeline into the store: the scene and its steps, their objects numbered along the way. */
function restore(scene: Scene, past: Scene[], future: Scene[]): void {
  let previous: Scene | null = null;
  for (const s of [...past, scene, ...future]) previous = carryIds(previous, s);
  useSceneStore.getState().resetTo(scene, past, future);
}

/**
 * Opens the database, puts what it keeps into the store (or, the first time, an earlier editor's
 * localStorage scene), then keeps every change. Resolves once the store holds what was kept, with
 * the function that stops autosave; never rejects (a failure is the status).
 */
export async function startAutosave(factory: IDBFactory | undefined = browserIndexedDb(), timeoutMs = OPEN_TIMEOUT_MS): Promise<() => void> {
  useAutosaveStatus.setState({ state: 'starting' }, true);
  if (!factory) {
    fail('This browser keeps nothing for this page (no IndexedDB): the scene will be lost on reload. Use Save to keep it.');
    return () => undefined;
  }
  let db: EditorDb;
  try {
    db = await bounded(EditorDb.open(factory), timeoutMs);
    const kept = await bounded(db.load(), timeoutMs);
    if (kept) restore(kept.scene, kept.past, kept.future);
    else {
      const legacy = loadLegacyScene();
      if (legacy) restore(legacy, [], []);
    }
  } catch (error) {
    fail(`The scene cannot be kept in this browser (${error instanceof Error ? error.message : String(error)}): it will be lost on reload. Use Save to keep it.`);
    return () => undefined;
  }
  database = db;
  const { scene, past, future } = useSceneStore.getState();
  void db.pruneAssets([scene, ...past, ...future]).catch(() => undefined);
  let running: Promise<void> | null = null;
  let again = false;
  const save = async () => {
    do {
      again = false;
      const s = useSceneStore.getState();
      const result = await db.saveTimeline(s.scene, s.past, s.future);
      if (result.ok) {
        useAutosaveStatus.setState({ state: 'saved' }, true);
        forgetLegacyScene();
      } else fail(`Your latest changes are not kept in this browser: ${result.reason}. Use Save to download the scene.`);
    } while (again);
    running = null;
  };
  const schedule = () => {
    if (running) again = true;
    else running = save();
  };
  settled = async () => {
    while (running) await running;
  };
  schedule();
  const unsubscribe = useSceneStore.subscribe((state, previous) => {
    if (state.scene !== previous.scene || state.past !== previous.past || state.future !== previous.future) schedule();
  });
  return () => {
    unsubscribe();
    if (database === db) database = null;
  };
}

let settled: () => Promise<void> = () => Promise.resolve();

/** Resolves once the saves under way are written (tests). */
export function autosaveSettled(): Promise<void> {
  return settled();
}

/** Keeps an asset's bytes beside the scene; a refusal becomes the autosave status. */
export async function keepAsset(asset: StoredAsset): Promise<void> {
  if (!database) return; // autosave is off, and its status says so already
  const result = await database.putAsset(asset);
  if (!result.ok) fail(`An imported file is not kept in this browser: ${result.reason}. It is on the server for now; use Save to keep the scene.`);
}

/** An asset's bytes as this browser keeps them, or null. */
export async function keptAsset(id: string): Promise<StoredAsset | null> {
  return database ? database.getAsset(id).catch(() => null) : null;
}

function bounded<T>(promise: Promise<T>, timeoutMs: number): Promise<T> {
  return new Promise<T>((resolve, reject) => {
    const timer = setTimeout(() => reject(new Error('the browser’s storage did not answer')), timeoutMs);
    promise.then(
      (value) => {
        clearTimeout(timer);
        resolve(value);
      },
      (error: unknown) => {
        clearTimeout(timer);
        reject(error instanceof Error ? error : new Error(String(error)));
      },
    );
  });
}

function browserIndexedDb(): IDBFactory | undefined {
  try {
    return typeof indexedDB === 'undefined' ? undefined : indexedDB;
  } catch {
    return undefined;
  }
}
