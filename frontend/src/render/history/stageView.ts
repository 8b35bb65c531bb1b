/**
 * What the stage shows, decided from what the user chose (a {@link Look}) and what there is: the
 * panel's own job (from Render), a render picked in the history, two compared, or, with none of
 * these, the history's stage render (the last one finished, found again after a reload). Pure.
 */
import type { HistoryEntry } from './RenderHistory';

/** The user's choice: the stage's own, one render of the history, or two compared. */
export type Look = { kind: 'stage' } | { kind: 'record'; id: string } | { kind: 'compare'; base: string; other: string };

/** What there is to show. */
export interface StageSources {
  /** True while the panel has a job of its own (starting, running, or ended in this page). */
  live: boolean;
  /** The server's id of that job; null before it is known. */
  liveJobId: string | null;
  /** The history's stage render for the editor's document (none after New). */
  stageEntry: HistoryEntry | null;
  /** The renders of the history, newest first. */
  entries: readonly HistoryEntry[];
}

export interface StageView {
  /** The render shown, when the history has it: the history marks it, Compare sets others against it. */
  shown: HistoryEntry | null;
  /** A render of the history shown instead of the panel's own job. */
  single: HistoryEntry | null;
  /** Two renders compared, the older first (left). */
  pair: readonly [HistoryEntry, HistoryEntry] | null;
}

export function stageView(look: Look, { live, liveJobId, stageEntry, entries }: StageSources): StageView {
  const find = (id: string) => entries.find((e) => e.record.id === id) ?? null;
  if (look.kind === 'compare') {
    const base = find(look.base);
    const other = find(look.other);
    if (base && other && base !== other) {
      const pair = base.record.finishedAt <= other.record.finishedAt ? ([base, other] as const) : ([other, base] as const);
      return { shown: base, single: null, pair };
    }
  }
  if (look.kind === 'record') {
    const picked = find(look.id);
    if (picked) return { shown: picked, single: picked, pair: null };
  }
  // the stage's own: its job, or else the history's stage render
  if (live) return { shown: liveJobId === null ? null : entries.find((e) => e.record.jobId === liveJobId) ?? null, single: null, pair: null };
  return { shown: stageEntry, single: stageEntry, pair: null };
}
