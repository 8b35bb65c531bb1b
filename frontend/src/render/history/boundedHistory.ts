/**
 * The history's list as a pure value: newest first, at most {@link HISTORY_LIMIT} renders. Adding one
 * beyond the bound drops the oldest, and says which, so that storage deletes them too.
 */
import type { RenderRecord } from './renderRecord';

/**
 * How many renders are kept: the last 12, a strip the width of the stage. Full-HD renders are small
 * as PNG (measured at 1920 x 1080: still-life 250 KB, six-materials 293 KB, glass-pattern with 4
 * random samples a pixel 352 KB), so 12 take about 4 MB of the browser's storage; even 12 that did
 * not compress at all (6.2 MB each) would stay under 75 MB.
 */
export const HISTORY_LIMIT = 12;

/** A list after a change, and the records that left it. */
export interface Trimmed {
  records: RenderRecord[];
  dropped: RenderRecord[];
}

/** Newest first: later `finishedAt` first, then the higher number (two renders in one millisecond). */
function newestFirst(a: RenderRecord, b: RenderRecord): number {
  return b.finishedAt - a.finishedAt || b.number - a.number;
}

/** The newest `limit` records of any list (duplicate ids: the first kept), and the rest. */
export function keepNewest(records: readonly RenderRecord[], limit: number = HISTORY_LIMIT): Trimmed {
  const seen = new Set<string>();
  const unique = records.filter((r) => !seen.has(r.id) && seen.add(r.id));
  const sorted = unique.sort(newestFirst);
  return { records: sorted.slice(0, Math.max(0, limit)), dropped: sorted.slice(Math.max(0, limit)) };
}

/** The list with `record` added (replacing one of the same id), bounded. */
export function addRecord(records: readonly RenderRecord[], record: RenderRecord, limit: number = HISTORY_LIMIT): Trimmed {
  return keepNewest([record, ...records.filter((r) => r.id !== record.id)], limit);
}

/** The number the next render gets: one more than the highest kept (1 for an empty history). */
export function nextNumber(records: readonly RenderRecord[]): number {
  return records.reduce((top, r) => Math.max(top, r.number), 0) + 1;
}
