/**
 * Test doubles for the render panel: a scriptable EventSource, a 2D context that records
 * what was drawn, and a history storage in memory. Only tests import this file.
 */
import type { EventSourceFactory, EventSourceLike } from '../api/jobs';
import type { HistoryStorage, StoredHistory } from '../render/history/historyStorage';
import type { RenderRecord } from '../render/history/renderRecord';

type Listener = (event: MessageEvent) => void;

/** An EventSource the test drives: `emit` sends a named event, `fail` an error. */
export class FakeEventSource implements EventSourceLike {
  readyState = 1;
  closed = false;
  private readonly listeners = new Map<string, Listener[]>();

  constructor(readonly url: string) {}

  addEventListener(type: string, listener: Listener): void {
    this.listeners.set(type, [...(this.listeners.get(type) ?? []), listener]);
  }

  close(): void {
    this.closed = true;
    this.readyState = 2;
  }

  /** Dispatches `event: type` with `data` (objects are sent as one JSON line). */
  emit(type: string, data: unknown): void {
    const text = typeof data === 'string' ? data : JSON.stringify(data);
    for (const listener of this.listeners.get(type) ?? []) listener({ data: text } as MessageEvent);
  }

  /** Dispatches an `error` with the given readyState: 0 reconnecting, 2 given up. */
  fail(readyState: 0 | 2): void {
    this.readyState = readyState;
    for (const listener of this.listeners.get('error') ?? []) listener({} as MessageEvent);
  }
}

/** A factory that remembers every stream it opened. */
export function fakeEventSources(): { factory: EventSourceFactory; opened: FakeEventSource[]; last: () => FakeEventSource } {
  const opened: FakeEventSource[] = [];
  const factory: EventSourceFactory = (url) => {
    const source = new FakeEventSource(url);
    opened.push(source);
    return source;
  };
  const last = () => {
    const source = opened.at(-1);
    if (!source) throw new Error('no event stream was opened');
    return source;
  };
  return { factory, opened, last };
}

/** One `drawImage(image, x, y, w, h)` call. */
export interface DrawCall {
  image: unknown;
  x: number;
  y: number;
  width: number;
  height: number;
}

/** A 2D context that records drawImage and clearRect calls. */
export function recordingContext(): { context: CanvasRenderingContext2D; draws: DrawCall[]; clears: number } {
  const record = { draws: [] as DrawCall[], clears: 0 };
  const context = {
    drawImage: (image: unknown, x: number, y: number, width: number, height: number) => {
      record.draws.push({ image, x, y, width, height });
    },
    clearRect: () => {
      record.clears++;
    },
  } as unknown as CanvasRenderingContext2D;
  return {
    context,
    draws: record.draws,
    get clears() {
      return record.clears;
    },
  };
}

/** A JobStatus JSON body as the server sends it. */
export function statusJson(overrides: Record<string, unknown> = {}): Record<string, unknown> {
  return {
    id: 'k3j',
    state: 'queued',
    progress: 0,
    elapsedMillis: 0,
    raysPerSecond: null,
    width: 64,
    height: 32,
    fileName: 'still-life.png',
    mediaType: 'image/png',
    error: null,
    ...overrides,
  };
}

/** A tile event's JSON, with a few bytes standing in for the PNG. */
export function tileJson(x: number, y: number, progress: number): Record<string, unknown> {
  return { x, y, width: 32, height: 32, png: btoa('\x89PNG tile'), progress };
}

/**
 * The render history's storage in memory, standing in for IndexedDB (happy-dom has none). A new
 * RenderHistory over the same storage is a reload; `failing` makes every call reject, as a storage
 * that breaks its promise never to would.
 */
export class MemoryHistoryStorage implements HistoryStorage {
  readonly records = new Map<string, RenderRecord>();
  stageId: string | null = null;
  failing = false;

  async load(): Promise<StoredHistory> {
    this.check();
    return { records: [...this.records.values()].map((r) => ({ ...r })), stageId: this.stageId };
  }

  async put(record: RenderRecord): Promise<void> {
    this.check();
    this.records.set(record.id, { ...record });
  }

  async remove(ids: readonly string[]): Promise<void> {
    this.check();
    for (const id of ids) this.records.delete(id);
  }

  async setStage(id: string | null): Promise<void> {
    this.check();
    this.stageId = id;
  }

  private check(): void {
    if (this.failing) throw new DOMException('The quota has been exceeded.', 'QuotaExceededError');
  }
}
