/**
 * The parsed triangles of the scene's meshes, shared by the views, the preview and the inspector.
 * Inline `obj` text is parsed once per distinct string (a Map keyed by the text: the string's hash
 * is computed once, and a drag or an edit that keeps the text never parses again); `file` meshes
 * are loaded once, through a loader the caller gives (the REST client), and kept; `asset` meshes
 * are loaded once per id and read in slices ({@link parseObjInChunks}), their progress shown.
 * A glTF model's shape is its bounding box, which the preview reports once it has loaded the model
 * ({@link MeshCache.setModel}). No React, no fetch: the hook in `hooks/useMeshes.ts` connects it.
 */
import { parseObj, parseObjInChunks } from './obj';
import type { ParsedObj } from './obj';
import type { GltfObject, MeshObject, MeshSourceField } from './types';

/** What is known about one mesh's triangles (a glTF model's: its bounding box as 12 triangles). */
export type MeshState =
  | { status: 'ready'; mesh: ParsedObj }
  | { status: 'loading'; /** The fraction read so far, when known. */ progress?: number }
  | { status: 'error'; message: string };

/** What a mesh's triangles are now (the cache's {@link MeshCache.get}, or a stand-in in tests). */
export type MeshLookup = (mesh: ModelRef) => MeshState;

/** What names a mesh's or a model's shape (a resolved object will do). */
export type ModelRef = Pick<MeshObject, 'type' | MeshSourceField> | Pick<GltfObject, 'type' | 'asset'>;

/** Loads an asset's bytes as text (a mesh's OBJ); rejects with an Error whose message can be shown. */
export type AssetTextLoader = (id: string) => Promise<string>;

/** A lookup for pure callers that have no cache: every mesh is still loading. */
export const NO_MESHES: MeshLookup = () => ({ status: 'loading' });

/** Loads a mesh file's OBJ text; rejects with an Error whose message can be shown. */
export type MeshFileLoader = (file: string) => Promise<string>;

/** Parses OBJ text into a state: ready, or the parse error naming its line. */
export function parseMeshState(text: string): MeshState {
  try {
    return { status: 'ready', mesh: parseObj(text) };
  } catch (error) {
    return { status: 'error', message: error instanceof Error ? error.message : String(error) };
  }
}

export class MeshCache {
  private readonly inline = new Map<string, MeshState>();
  private readonly files = new Map<string, MeshState>();
  private readonly assets = new Map<string, MeshState>();
  private readonly models = new Map<string, MeshState>();
  private readonly listeners = new Set<() => void>();
  private changes = 0;

  /** @param maxInline how many distinct inline texts are kept (the least recently used goes first) */
  constructor(private readonly maxInline = 16) {}

  /** A number that changes whenever a file's state changes (for `useSyncExternalStore`). */
  readonly version = (): number => this.changes;

  /** Calls `listener` whenever a file's state changes; returns the unsubscribe function. */
  readonly subscribe = (listener: () => void): (() => void) => {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  };

  /**
   * The state of a mesh's triangles: its inline text parsed (synchronously, once per text), or its
   * file's state ('loading' until {@link ensure} has loaded it), or an error if it names neither or both.
   */
  get(mesh: ModelRef): MeshState {
    if (mesh.type === 'gltf') return this.models.get(mesh.asset) ?? { status: 'loading' };
    const sources = [mesh.obj, mesh.file, mesh.asset].filter((s) => s !== undefined).length;
    if (sources !== 1) {
      const message = sources === 0 ? 'a mesh needs its OBJ text in "obj", a "file" name or an "asset" id' : 'give the mesh one of "obj", "file" and "asset", not more';
      return { status: 'error', message };
    }
    if (mesh.obj !== undefined) return this.parseInline(mesh.obj);
    if (mesh.asset !== undefined) return this.assets.get(mesh.asset) ?? { status: 'loading' };
    return this.files.get(mesh.file!) ?? { status: 'loading' };
  }

  /** Keeps an asset's parsed OBJ (just imported: it is not read again). */
  putAsset(id: string, mesh: ParsedObj): void {
    this.assets.set(id, { status: 'ready', mesh });
    this.changed();
  }

  /** Starts loading and reading an asset's OBJ unless it is known, loading or failed already. */
  ensureAsset(id: string, load: AssetTextLoader): void {
    if (this.assets.has(id)) return;
    let pending: MeshState = { status: 'loading', progress: 0 };
    this.assets.set(id, pending);
    const current = () => this.assets.get(id) === pending;
    const settle = (state: MeshState) => {
      if (!current()) return; // cleared meanwhile
      pending = state;
      this.assets.set(id, state);
      this.changed();
    };
    Promise.resolve()
      .then(() => load(id))
      .then((text) => parseObjInChunks(text, { onProgress: (progress) => progress < 1 && settle({ status: 'loading', progress }) }))
      .then(
        (mesh) => settle({ status: 'ready', mesh }),
        (error: unknown) => settle({ status: 'error', message: `${id.slice(0, 15)}…: ${error instanceof Error ? error.message : String(error)}` }),
      );
  }

  /** Records what is known of a glTF model's shape (the preview loads it). */
  setModel(id: string, state: MeshState): void {
    this.models.set(id, state);
    this.changed();
  }

  /** Whether the model's state is known or on its way (the preview starts each load once). */
  hasModel(id: string): boolean {
    return this.models.has(id);
  }

  /** Inline OBJ text, parsed once per distinct string. */
  parseInline(text: string): MeshState {
    let state = this.inline.get(text);
    if (state) {
      this.inline.delete(text); // most recently used goes last
    } else {
      state = parseMeshState(text);
      if (this.inline.size >= this.maxInline) this.inline.delete(this.inline.keys().next().value!);
    }
    this.inline.set(text, state);
    return state;
  }

  /** Starts loading a mesh file unless it is loaded, loading or failed already. */
  ensure(file: string, load: MeshFileLoader): void {
    if (this.files.has(file)) return;
    const pending: MeshState = { status: 'loading' };
    this.files.set(file, pending);
    let request: Promise<string>;
    try {
      request = load(file);
    } catch (error) {
      request = Promise.reject(error);
    }
    request
      .then(parseMeshState, (error: unknown): MeshState => ({ status: 'error', message: error instanceof Error ? error.message : String(error) }))
      .then((state) => {
        if (this.files.get(file) !== pending) return; // cleared meanwhile
        this.files.set(file, state.status === 'error' ? { status: 'error', message: `${file}: ${state.message}` } : state);
        this.changed();
      });
  }

  /** Forgets everything (tests; a failed file is tried again after this). */
  clear(): void {
    this.inline.clear();
    this.files.clear();
    this.assets.clear();
    this.models.clear();
    this.changed();
  }

  private changed(): void {
    this.changes++;
    for (const listener of this.listeners) listener();
  }
}
