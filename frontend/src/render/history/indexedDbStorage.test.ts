import { afterEach, describe, expect, it, vi } from 'vitest';
import { NO_STORAGE } from './historyStorage';
import { indexedDbStorage, STORAGE_TIMEOUT_MS } from './indexedDbStorage';

/** An IDBFactory whose open request does what `behave` makes it do. */
function factory(behave: (request: Record<string, (() => void) | unknown>) => void): IDBFactory {
  return {
    open: () => {
      const request: Record<string, unknown> = {};
      queueMicrotask(() => behave(request as Record<string, () => void>));
      return request as unknown as IDBOpenDBRequest;
    },
  } as unknown as IDBFactory;
}

const nothing = { records: [], stageId: null };

describe('indexedDbStorage', () => {
  afterEach(() => {
    vi.useRealTimers();
  });

  it('is no storage where the browser has no IndexedDB', () => {
    expect(indexedDbStorage(undefined)).toBe(NO_STORAGE);
  });

  it('loads nothing and keeps nothing, silently, when the database cannot be opened', async () => {
    const storage = indexedDbStorage(factory((r) => (r.onerror as () => void)()));
    await expect(storage.load()).resolves.toEqual(nothing);
    await expect(storage.setStage('x')).resolves.toBeUndefined();
    const throwing = indexedDbStorage({ open: () => { throw new DOMException('denied', 'SecurityError'); } } as unknown as IDBFactory);
    await expect(throwing.load()).resolves.toEqual(nothing);
  });

  it('gives up on an open that never answers (an upgrade blocked by another tab) after its bound', async () => {
    vi.useFakeTimers();
    const storage = indexedDbStorage(factory(() => undefined));
    let loaded: unknown = 'pending';
    void storage.load().then((value) => (loaded = value));
    await vi.advanceTimersByTimeAsync(STORAGE_TIMEOUT_MS - 1);
    expect(loaded).toBe('pending');
    await vi.advanceTimersByTimeAsync(1);
    expect(loaded).toEqual(nothing);
  });
});
