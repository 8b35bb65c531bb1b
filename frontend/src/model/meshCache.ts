/**
 * The parsed triangles of the scene's meshes, shared by the views, the preview and the inspector.
 * Inline `obj` text is parsed once per distinct string (a Map keyed by the text: the string's hash
 * is computed once, and a drag or an edit that keeps the text never parses again); `file` meshes
 * are loaded once, through a loader the caller gives (the REST client), and kept. No React, no
 * fetch: the hook in `hooks/useMeshes.ts` connects it to both.
 */
import { parseObj } from './obj';
import type { ParsedObj } from './obj';
import type { MeshObject } from './types';

/** What is known about one mesh's triangles. */
export type MeshState =
  | { status: 'ready'; mesh: ParsedObj }
  | { status: 'loading' }
  | { status: 'error'; message: string };

/** What a mesh's triangles are now (the cache's {@link MeshCache.get}, or a stand-in in tests). */
export type MeshLookup = (mesh: MeshObject) => MeshState;

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
  get(mesh: MeshObject): MeshState {
    if ((mesh.obj === undefined) === (mesh.file === undefined)) {
      const message = mesh.obj === undefined ? 'a mesh needs its OBJ text ("obj") or a file name ("file")' : 'give the mesh either "obj" or "file", not both';
      return { status: 'error', message };
    }
    if (mesh.obj !== undefined) return this.parseInline(mesh.obj);
    return this.files.get(mesh.file!) ?? { status: 'loading' };
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
    this.changed();
  }

  private changed(): void {
    this.changes++;
    for (const listener of this.listeners) listener();
  }
}
