import { describe, expect, it } from 'vitest';
import type { HistoryEntry } from './RenderHistory';
import { stageView, type StageSources } from './stageView';

function entry(n: number): HistoryEntry {
  return {
    record: {
      id: `r${n}`, jobId: `job${n}`, number: n, finishedAt: n * 1000, renderMillis: 1, raysPerSecond: null, width: 4, height: 3,
      samples: 16, adaptive: true, sceneName: 's', filename: 's.png', scene: { objects: [] }, image: new Blob(), thumbnail: null,
    },
    url: `blob:${n}`,
    thumbnailUrl: `blob:${n}`,
  };
}

const [one, two, three] = [entry(1), entry(2), entry(3)];
const entries = [three, two, one];
const idle: StageSources = { live: false, liveJobId: null, stageEntry: three, entries };

describe('stageView', () => {
  it('shows the history\'s stage render when the panel has no job of its own (after a reload)', () => {
    expect(stageView({ kind: 'stage' }, idle)).toEqual({ shown: three, single: three, pair: null });
    expect(stageView({ kind: 'stage' }, { ...idle, stageEntry: null })).toEqual({ shown: null, single: null, pair: null });
  });

  it('shows its own job over the stage render, knowing it in the history by its job id', () => {
    expect(stageView({ kind: 'stage' }, { ...idle, live: true, liveJobId: 'job2' })).toEqual({ shown: two, single: null, pair: null });
    expect(stageView({ kind: 'stage' }, { ...idle, live: true, liveJobId: 'job9' })).toEqual({ shown: null, single: null, pair: null });
  });

  it('shows a render picked in the history, even over a job of its own', () => {
    expect(stageView({ kind: 'record', id: 'r1' }, { ...idle, live: true, liveJobId: 'job3' })).toEqual({ shown: one, single: one, pair: null });
  });

  it('compares two renders, the older on the left, whichever was picked first', () => {
    expect(stageView({ kind: 'compare', base: 'r3', other: 'r1' }, idle)).toEqual({ shown: three, single: null, pair: [one, three] });
    expect(stageView({ kind: 'compare', base: 'r1', other: 'r2' }, idle).pair).toEqual([one, two]);
  });

  it('falls back to the stage when a chosen render has left the history', () => {
    expect(stageView({ kind: 'record', id: 'gone' }, idle)).toEqual({ shown: three, single: three, pair: null });
    expect(stageView({ kind: 'compare', base: 'r3', other: 'gone' }, idle)).toEqual({ shown: three, single: three, pair: null });
    expect(stageView({ kind: 'compare', base: 'r3', other: 'r3' }, idle).pair).toBeNull();
  });
});
