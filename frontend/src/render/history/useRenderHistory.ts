import { useSyncExternalStore } from 'react';
import type { HistorySnapshot, RenderHistory } from './RenderHistory';

/** The history's current list and stage render; re-renders on every change. */
export function useRenderHistory(history: RenderHistory): HistorySnapshot {
  return useSyncExternalStore(history.subscribe, history.snapshot);
}
