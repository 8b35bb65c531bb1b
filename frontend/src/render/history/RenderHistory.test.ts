import { beforeEach, describe, expect, it, vi } from 'vitest';
import { MemoryHistoryStorage } from '../../test/renderFakes';
import { RenderHistory } from './RenderHistory';
import type { FinishedRender } from './renderRecord';

let clock = 1_000_000;
function finished(name: string, overrides: Partial<FinishedRender> = {}): FinishedRender {
  clock += 1000;
  return {
    jobId: `job-${name}`,
    finishedAt: clock,
    sentScene: { name, objects: [] },
    image: new Blob([`png of ${name}`], { type: 'image/png' }),
    filename: `${name}.png`,
    width: 64,
    height: 32,
    renderMillis: 100,
    raysPerSecond: 1e6,
    ...overrides,
  };
}

const noThumbnail = async () => null;
const names = (history: RenderHistory) => history.snapshot().entries.map((e) => e.record.sceneName);

describe('RenderHistory', () => {
  let revoked: string[];
  beforeEach(() => {
    let next = 0;
    revoked = [];
    vi.spyOn(URL, 'createObjectURL').mockImplementation(() => `blob:test/${++next}`);
    vi.spyOn(URL, 'revokeObjectURL').mockImplementation((url) => void revoked.push(url));
  });

  it('keeps each finished render, newest first, as the stage render, with its thumbnail; and writes it through', async () => {
    const storage = new MemoryHistoryStorage();
    const thumb = new Blob(['small']);
    const history = new RenderHistory(storage, { makeThumbnail: async () => thumb });
    const first = await history.add(finished('a'));
    const second = await history.add(finished('b'));
    expect(names(history)).toEqual(['b', 'a']);
    expect([first?.number, second?.number]).toEqual([1, 2]);
    expect(history.snapshot().stageId).toBe(second?.id);
    const entry = history.find(second?.id)!;
    expect(entry.record.thumbnail).toBe(thumb);
    expect(entry.thumbnailUrl).not.toBe(entry.url);
    expect([...storage.records.keys()].sort()).toEqual([first?.id, second?.id].sort());
    expect(storage.stageId).toBe(second?.id);
  });

  it('drops the oldest beyond its bound from the list and from storage, and revokes its URLs', async () => {
    const storage = new MemoryHistoryStorage();
    const history = new RenderHistory(storage, { limit: 3, makeThumbnail: noThumbnail });
    for (const name of ['a', 'b', 'c']) await history.add(finished(name));
    const oldest = history.snapshot().entries.at(-1)!;
    await history.add(finished('d'));
    expect(names(history)).toEqual(['d', 'c', 'b']);
    expect(storage.records.size).toBe(3);
    expect(storage.records.has(oldest.record.id)).toBe(false);
    expect(revoked).toEqual([oldest.url]);
  });

  it('is found again after a reload, numbering on', async () => {
    const storage = new MemoryHistoryStorage();
    const before = new RenderHistory(storage, { makeThumbnail: noThumbnail });
    await before.add(finished('a'));
    const last = await before.add(finished('b'));

    const after = new RenderHistory(storage, { makeThumbnail: noThumbnail });
    await after.whenLoaded();
    expect(names(after)).toEqual(['b', 'a']);
    after.noteDocument(1);
    expect(after.stageEntry(1)?.record.id).toBe(last?.id);
    expect(after.stageEntry(1)?.record.scene).toEqual({ name: 'b', objects: [] });
    expect((await after.add(finished('c')))?.number).toBe(3);
  });

  it('bounds what storage holds on loading (two tabs may each have added), and drops what it cannot read', async () => {
    const storage = new MemoryHistoryStorage();
    const writer = new RenderHistory(storage, { limit: 5, makeThumbnail: noThumbnail });
    for (const name of ['a', 'b', 'c', 'd', 'e']) await writer.add(finished(name));
    storage.records.set('broken', { id: 'broken' } as never);
    const reader = new RenderHistory(storage, { limit: 3, makeThumbnail: noThumbnail });
    await reader.whenLoaded();
    expect(names(reader)).toEqual(['e', 'd', 'c']);
    await vi.waitFor(() => expect([...storage.records.values()].map((r) => r.sceneName).sort()).toEqual(['c', 'd', 'e']));
  });

  it('clears the stage, not the list, when the document changes; a reload then shows no stage render', async () => {
    const storage = new MemoryHistoryStorage();
    const history = new RenderHistory(storage, { makeThumbnail: noThumbnail });
    history.noteDocument(1);
    const record = await history.add(finished('a'));
    history.noteDocument(1);
    expect(history.stageEntry(1)?.record.id).toBe(record?.id);
    // the new document's panel asks before it says which document it is: nothing already
    expect(history.stageEntry(2)).toBeNull();
    history.noteDocument(2);
    expect(history.snapshot().stageId).toBeNull();
    expect(names(history)).toEqual(['a']);
    await vi.waitFor(() => expect(storage.stageId).toBeNull());

    const reloaded = new RenderHistory(storage, { makeThumbnail: noThumbnail });
    await reloaded.whenLoaded();
    reloaded.noteDocument(1);
    expect(reloaded.stageEntry(1)).toBeNull();
    expect(names(reloaded)).toEqual(['a']);
  });

  it('lets a new document started before storage answered win over the stage storage had', async () => {
    const storage = new MemoryHistoryStorage();
    const record = await new RenderHistory(storage, { makeThumbnail: noThumbnail }).add(finished('a'));
    expect(storage.stageId).toBe(record?.id);
    const history = new RenderHistory(storage, { makeThumbnail: noThumbnail });
    history.noteDocument(1);
    history.noteDocument(2);
    await history.whenLoaded();
    expect(history.stageEntry(2)).toBeNull();
    expect(names(history)).toEqual(['a']);
  });

  it('works on in memory when storage fails, and without a thumbnail when none can be made', async () => {
    const storage = new MemoryHistoryStorage();
    storage.failing = true;
    const history = new RenderHistory(storage, { makeThumbnail: () => Promise.reject(new Error('no canvas')) });
    await history.whenLoaded();
    const record = await history.add(finished('a'));
    expect(names(history)).toEqual(['a']);
    const entry = history.find(record?.id)!;
    expect(entry.record.thumbnail).toBeNull();
    expect(entry.thumbnailUrl).toBe(entry.url);
  });

  it('keeps no render of something that is not a scene', async () => {
    const history = new RenderHistory(new MemoryHistoryStorage(), { makeThumbnail: noThumbnail });
    expect(await history.add(finished('a', { sentScene: '{ broken' }))).toBeNull();
    expect(names(history)).toEqual([]);
  });
});
