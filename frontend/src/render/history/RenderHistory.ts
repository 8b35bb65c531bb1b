/**
 * The session's last renders ({@link HISTORY_LIMIT} of them), and which one the stage shows when no
 * job of its own is on it: the last render finished, until New, Open or an example starts another
 * document. Kept in memory as the page's one list (like the mesh cache, outside the scene store:
 * renders are not edits and have no undo) and written through to a {@link HistoryStorage}, so a
 * reload finds both again. No React: `useRenderHistory` connects it.
 *
 * The list is the session's, not the document's: New and Open clear the stage, not the history, so
 * a render of the scene before New can still be compared or restored.
 */
import { addRecord, HISTORY_LIMIT, keepNewest, nextNumber } from './boundedHistory';
import type { HistoryStorage } from './historyStorage';
import { readRecord, recordOf, type FinishedRender, type RenderRecord } from './renderRecord';
import { makeThumbnail } from './thumbnail';

/** A render of the list, with the object URLs the page shows it by. */
export interface HistoryEntry {
  record: RenderRecord;
  /** The image's object URL (stage, comparison, Download); revoked when the entry leaves the list. */
  url: string;
  /** The thumbnail's object URL, or the image's when it has none. */
  thumbnailUrl: string;
}

/** What the page draws from: a new object after every change (for `useSyncExternalStore`). */
export interface HistorySnapshot {
  /** Newest first. */
  entries: readonly HistoryEntry[];
  /** The render the stage shows when it has no job of its own; null when cleared. */
  stageId: string | null;
}

/** Makes a thumbnail of an image of the given size; null when it cannot. */
export type ThumbnailMaker = (image: Blob, width: number, height: number) => Promise<Blob | null>;

export interface RenderHistoryOptions {
  limit?: number;
  makeThumbnail?: ThumbnailMaker;
}

export class RenderHistory {
  private snap: HistorySnapshot = { entries: [], stageId: null };
  private readonly listeners = new Set<() => void>();
  private readonly limit: number;
  private readonly thumbnail: ThumbnailMaker;
  /** The editor's document the stage belongs to; undefined until the panel first says. */
  private document: number | undefined;
  /** True once this page chose the stage (a render, a new document): storage's choice no longer counts. */
  private stageChosen = false;
  private readonly loaded: Promise<void>;

  constructor(private readonly storage: HistoryStorage, options: RenderHistoryOptions = {}) {
    this.limit = options.limit ?? HISTORY_LIMIT;
    this.thumbnail = options.makeThumbnail ?? makeThumbnail;
    this.loaded = this.load();
  }

  readonly subscribe = (listener: () => void): (() => void) => {
    this.listeners.add(listener);
    return () => this.listeners.delete(listener);
  };

  readonly snapshot = (): HistorySnapshot => this.snap;

  /** Resolves once what storage kept is in the list (at once, and for good, if it kept nothing). */
  whenLoaded(): Promise<void> {
    return this.loaded;
  }

  find(id: string | null | undefined): HistoryEntry | null {
    return this.snap.entries.find((e) => e.record.id === id) ?? null;
  }

  /** The render the stage shows for `documentId` when it has no job of its own: none in a newer document. */
  stageEntry(documentId: number): HistoryEntry | null {
    if (this.document !== undefined && this.document !== documentId) return null;
    return this.find(this.snap.stageId);
  }

  /** The editor's document is `documentId` now; a change (New, Open, an example) clears the stage. */
  noteDocument(documentId: number): void {
    const changed = this.document !== undefined && this.document !== documentId;
    this.document = documentId;
    if (!changed) return;
    this.stageChosen = true;
    if (this.snap.stageId === null) return;
    this.publish(this.records(), null);
    void this.storage.setStage(null).catch(() => undefined);
  }

  /**
   * Keeps a finished render (its thumbnail made first, within a bound) as the newest of the list and
   * the stage's render; the oldest beyond the bound leaves the list and storage. Resolves with the
   * record, or null when what was rendered is no scene.
   */
  readonly add = async (render: FinishedRender): Promise<RenderRecord | null> => {
    const thumbnail = await this.thumbnail(render.image, render.width, render.height).catch(() => null);
    await this.loaded;
    const record = recordOf(render, nextNumber(this.records()), thumbnail);
    if (!record) return null;
    const { records, dropped } = addRecord(this.records(), record, this.limit);
    this.stageChosen = true;
    this.publish(records, record.id);
    await Promise.all([
      this.storage.put(record),
      this.storage.remove(dropped.map((r) => r.id)),
      this.storage.setStage(record.id),
    ]).catch(() => undefined);
    return record;
  };

  /** Revokes every object URL and empties the list (tests; a page never needs to). */
  dispose(): void {
    this.publish([], null);
  }

  private records(): RenderRecord[] {
    return this.snap.entries.map((e) => e.record);
  }

  private async load(): Promise<void> {
    let stored;
    try {
      stored = await this.storage.load();
    } catch {
      return;
    }
    const readable = stored.records.map(readRecord).filter((r): r is RenderRecord => r !== null);
    const unreadable = stored.records.filter((r) => readRecord(r) === null).map(idOf).filter((id): id is string => id !== null);
    const { records, dropped } = keepNewest([...this.records(), ...readable], this.limit);
    const stageId = this.stageChosen ? this.snap.stageId : stored.stageId;
    this.publish(records, records.some((r) => r.id === stageId) ? stageId : null);
    const gone = [...unreadable, ...dropped.map((r) => r.id)];
    if (gone.length > 0) await this.storage.remove(gone).catch(() => undefined);
  }

  /** Makes the new snapshot: entries kept keep their URLs, new ones get theirs, the rest are revoked. */
  private publish(records: readonly RenderRecord[], stageId: string | null): void {
    const old = new Map(this.snap.entries.map((e) => [e.record, e]));
    const entries = records.map((record) => old.get(record) ?? entryOf(record));
    const kept = new Set(entries);
    for (const entry of this.snap.entries) if (!kept.has(entry)) revoke(entry);
    this.snap = { entries, stageId };
    for (const listener of this.listeners) listener();
  }
}

function entryOf(record: RenderRecord): HistoryEntry {
  const url = URL.createObjectURL(record.image);
  return { record, url, thumbnailUrl: record.thumbnail ? URL.createObjectURL(record.thumbnail) : url };
}

function revoke(entry: HistoryEntry): void {
  URL.revokeObjectURL(entry.url);
  if (entry.thumbnailUrl !== entry.url) URL.revokeObjectURL(entry.thumbnailUrl);
}

function idOf(value: unknown): string | null {
  const id = typeof value === 'object' && value !== null ? (value as { id?: unknown }).id : undefined;
  return typeof id === 'string' ? id : null;
}
