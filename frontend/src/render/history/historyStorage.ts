/**
 * Where the render history outlives a reload. The editor works the same without it: every method
 * resolves, never rejects, and a storage that cannot keep anything (private browsing, a full disk,
 * no IndexedDB) simply gives back nothing on the next load.
 */
import type { RenderRecord } from './renderRecord';

/** What a reload finds. */
export interface StoredHistory {
  /** As stored, in any order; the history checks and bounds them. */
  records: unknown[];
  /** The render the stage showed last; null after New, Open or an example cleared it. */
  stageId: string | null;
}

export interface HistoryStorage {
  load(): Promise<StoredHistory>;
  /** Adds a record, or replaces the one of the same id (when its thumbnail is made). */
  put(record: RenderRecord): Promise<void>;
  remove(ids: readonly string[]): Promise<void>;
  setStage(id: string | null): Promise<void>;
}

/** Keeps nothing: the history lasts as long as the page. */
export const NO_STORAGE: HistoryStorage = {
  load: async () => ({ records: [], stageId: null }),
  put: async () => undefined,
  remove: async () => undefined,
  setStage: async () => undefined,
};
