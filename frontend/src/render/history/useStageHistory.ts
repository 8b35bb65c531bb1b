import { useCallback, useEffect, useState } from 'react';
import type { Scene } from '../../model/types';
import { useSceneStore } from '../../store/sceneStore';
import type { HistoryEntry, RenderHistory } from './RenderHistory';
import { stageView, type Look, type StageView } from './stageView';
import { useRenderHistory } from './useRenderHistory';

/** What {@link useStageHistory} needs from the stage. */
export interface StageHistoryOptions {
  /** True while the stage has a job of its own (starting, running, or ended in this page). */
  live: boolean;
  /** That job's id, once known. */
  liveJobId: string | null;
  /** Called when the stage should show the render (a render picked, compared or restored). */
  onShow?: () => void;
  /** Puts a scene back in the editor; by default the store's `setScene` (one undo step, ids kept). */
  onRestoreScene?: (scene: Scene) => void;
}

/** The history's side of the stage: what it shows, and the strip's actions. */
export interface StageHistory extends StageView {
  entries: readonly HistoryEntry[];
  /** Shows one render of the history. */
  show: (id: string) => void;
  /** Compares a render with the one shown. */
  compare: (id: string) => void;
  /** Puts a render's scene back in the editor and shows that render. */
  restore: (id: string) => void;
  /** Back to the stage's own: its job, or the history's stage render (a new Render does this). */
  reset: () => void;
  /** Ends a comparison, showing the render the other was compared with. */
  endCompare: () => void;
}

const restoreInStore = (scene: Scene) => useSceneStore.getState().setScene(scene);

/**
 * Connects the stage to the render history: tells the history which document the editor holds
 * (the store's `documentId`: New, Open and the examples clear the stage's render), and keeps what
 * the user chose to look at.
 */
export function useStageHistory(history: RenderHistory, { live, liveJobId, onShow, onRestoreScene = restoreInStore }: StageHistoryOptions): StageHistory {
  const { entries } = useRenderHistory(history);
  const documentId = useSceneStore((s) => s.documentId);
  useEffect(() => history.noteDocument(documentId), [history, documentId]);
  const [look, setLook] = useState<Look>({ kind: 'stage' });
  const view = stageView(look, { live, liveJobId, stageEntry: history.stageEntry(documentId), entries });
  const reset = useCallback(() => setLook({ kind: 'stage' }), []);

  const showing = (next: Look) => {
    setLook(next);
    onShow?.();
  };
  return {
    ...view,
    entries,
    show: (id) => showing({ kind: 'record', id }),
    compare: (id) => {
      if (view.shown) showing({ kind: 'compare', base: view.shown.record.id, other: id });
    },
    restore: (id) => {
      const entry = history.find(id);
      if (!entry) return;
      onRestoreScene(entry.record.scene);
      showing({ kind: 'record', id });
    },
    reset,
    endCompare: () => setLook(view.shown ? { kind: 'record', id: view.shown.record.id } : { kind: 'stage' }),
  };
}
