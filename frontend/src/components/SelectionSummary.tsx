import { useSceneStore } from '../store/sceneStore';

/**
 * Shown while several objects and lights are selected: how many, and the edits that act on all of
 * them (each one undo step). The fields below belong to the last one picked.
 */
export function SelectionSummary() {
  const count = useSceneStore((s) => s.selectedItems.length);
  if (count < 2) return null;
  const s = useSceneStore.getState;
  return (
    <section className="selection-summary" aria-label="Selection">
      <p role="status">
        <strong>{count} selected</strong> — drag one to move them all; the fields below are the last one picked.
      </p>
      <div className="selection-summary__actions">
        <button type="button" className="small" title="Duplicate every selected object and light (Ctrl+D)" onClick={() => s().duplicateSelected()}>
          Duplicate {count}
        </button>
        <button type="button" className="small" title="Delete every selected object and light (Delete)" onClick={() => s().deleteSelected()}>
          Delete {count}
        </button>
        <button type="button" className="small" title="Select nothing (Escape)" onClick={() => s().select(null)}>
          Clear selection
        </button>
      </div>
    </section>
  );
}
