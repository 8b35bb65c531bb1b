/**
 * Undo/redo as pure functions over an immutable timeline: `past` (oldest first), the
 * `present` value and `future` (next redo first). A push forgets the future.
 */

export interface Timeline<T> {
  past: T[];
  present: T;
  future: T[];
}

/** How many steps back undo can go. */
export const HISTORY_LIMIT = 200;

export function startTimeline<T>(present: T): Timeline<T> {
  return { past: [], present, future: [] };
}

/** Records a new present value; the old one becomes the last undo step. */
export function push<T>(timeline: Timeline<T>, next: T, limit = HISTORY_LIMIT): Timeline<T> {
  const past = [...timeline.past, timeline.present];
  return { past: past.length > limit ? past.slice(past.length - limit) : past, present: next, future: [] };
}

/** Steps back one entry; unchanged when there is nothing to undo. */
export function undo<T>(timeline: Timeline<T>): Timeline<T> {
  if (timeline.past.length === 0) return timeline;
  const past = timeline.past.slice(0, -1);
  return { past, present: timeline.past[timeline.past.length - 1], future: [timeline.present, ...timeline.future] };
}

/** Steps forward one entry; unchanged when there is nothing to redo. */
export function redo<T>(timeline: Timeline<T>): Timeline<T> {
  if (timeline.future.length === 0) return timeline;
  const [present, ...future] = timeline.future;
  return { past: [...timeline.past, timeline.present], present, future };
}
