import { describe, expect, it } from 'vitest';
import { addRecord, HISTORY_LIMIT, keepNewest, nextNumber } from './boundedHistory';
import type { RenderRecord } from './renderRecord';

function record(number: number, finishedAt = number * 1000): RenderRecord {
  return {
    id: `r${number}`,
    jobId: `job${number}`,
    number,
    finishedAt,
    renderMillis: 10,
    raysPerSecond: null,
    width: 4,
    height: 3,
    samples: 16,
    adaptive: true,
    sceneName: 'scene',
    filename: 'scene.png',
    scene: { objects: [] },
    image: new Blob(['png']),
    thumbnail: null,
  };
}

const numbers = (records: RenderRecord[]) => records.map((r) => r.number);

describe('boundedHistory', () => {
  it('keeps the last 12 renders, newest first, and says which left', () => {
    let list: RenderRecord[] = [];
    const dropped: number[] = [];
    for (let n = 1; n <= 15; n++) {
      const next = addRecord(list, record(n));
      list = next.records;
      dropped.push(...numbers(next.dropped));
    }
    expect(HISTORY_LIMIT).toBe(12);
    expect(numbers(list)).toEqual([15, 14, 13, 12, 11, 10, 9, 8, 7, 6, 5, 4]);
    expect(dropped).toEqual([1, 2, 3]);
  });

  it('orders by finishing time, then by number, and keeps one record an id', () => {
    const same = keepNewest([record(1, 5), record(3, 9), record(2, 5), record(3, 9)], 10);
    expect(numbers(same.records)).toEqual([3, 2, 1]);
    expect(same.dropped).toEqual([]);
    expect(numbers(keepNewest([record(1), record(2), record(3)], 2).dropped)).toEqual([1]);
    expect(numbers(addRecord([record(1), record(2)], { ...record(2), sceneName: 'again' }).records)).toEqual([2, 1]);
  });

  it('numbers on from the highest kept', () => {
    expect(nextNumber([])).toBe(1);
    expect(nextNumber([record(7), record(9), record(8)])).toBe(10);
  });
});
