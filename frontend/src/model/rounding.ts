/**
 * Numbers as the editor saves them: without binary float noise. Sums such as -0.2 - 0.4 give
 * -0.6000000000000001; twelve significant digits drop that noise (it lives in the 16th-17th digit)
 * and keep everything a person types or a drag can mean (a micrometre at a kilometre). Pure.
 */
import type { Scene } from './types';

/** Significant digits a saved number keeps. */
export const SAVED_DIGITS = 12;

/** A number without float noise (-0.6000000000000001 → -0.6); non-finite numbers and -0 → as they are / 0. */
export function roundNumber(value: number): number {
  if (!Number.isFinite(value)) return value;
  const rounded = Number(value.toPrecision(SAVED_DIGITS));
  return rounded === 0 ? 0 : rounded;
}

/**
 * `next` with every number it changed relative to `previous` rounded by {@link roundNumber}; what
 * it kept (the same object, or an equal number at the same place) stays exactly as it was, so a
 * loaded file's own digits are never touched by an edit elsewhere. Arrays and objects none of whose
 * numbers change are returned as they are (the very same object), so the editor's ids, kept per
 * object, survive.
 */
export function roundChanged<T>(previous: unknown, next: T): T {
  if (Object.is(previous, next)) return next;
  if (typeof next === 'number') return (previous === next ? next : roundNumber(next)) as T;
  if (next === null || typeof next !== 'object') return next;
  const before = (previous !== null && typeof previous === 'object' ? previous : {}) as Record<string, unknown>;
  let changed = false;
  const out: Record<string, unknown> | unknown[] = Array.isArray(next) ? [] : {};
  for (const [k, v] of Object.entries(next)) {
    const r = roundChanged(before[k], v);
    if (!Object.is(r, v)) changed = true;
    (out as Record<string, unknown>)[k] = r;
  }
  return (changed ? out : next) as T;
}

/** The scene after an edit, with the numbers the edit wrote saved rounded (see {@link roundChanged}). */
export const roundEdit = (before: Scene, after: Scene): Scene => roundChanged(before, after);
