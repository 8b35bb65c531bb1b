import { useEffect } from 'react';
import type { GizmoMode } from '../model/gizmo';
import { useSceneStore } from '../store/sceneStore';

/** True when a key press belongs to a text field (the browser's own undo and editing apply). */
function inField(target: EventTarget | null): boolean {
  const el = target as HTMLElement | null;
  if (!el || !el.tagName) return false;
  return el.isContentEditable || ['INPUT', 'TEXTAREA', 'SELECT'].includes(el.tagName);
}

/** W, E, R: the 3D view's move, rotate and scale handles (as in Blender and the three.js editor). */
const GIZMO_KEYS: Record<string, GizmoMode> = { w: 'translate', e: 'rotate', r: 'scale' };

/**
 * Keyboard shortcuts of the editor: Ctrl/Cmd+Z undo, Ctrl/Cmd+Shift+Z and Ctrl+Y redo,
 * Delete/Backspace deletes the selection, Ctrl/Cmd+D duplicates it, Escape clears it; W, E, R pick
 * the 3D handles (move, rotate, scale), F frames the selection in the 3D view.
 * Ignored while focus is in an input, so typing is never hijacked.
 */
export function useEditorShortcuts(): void {
  useEffect(() => {
    const onKeyDown = (event: KeyboardEvent) => {
      if (inField(event.target) || event.altKey) return;
      const s = useSceneStore.getState();
      const mod = event.ctrlKey || event.metaKey;
      const key = event.key.toLowerCase();
      let handled = true;
      if (mod && key === 'z') {
        if (event.shiftKey) s.redo();
        else s.undo();
      } else if (mod && key === 'y') s.redo();
      else if (mod && key === 'd') s.duplicateSelected();
      else if (!mod && (event.key === 'Delete' || event.key === 'Backspace')) s.deleteSelected();
      else if (!mod && event.key === 'Escape') s.select(null);
      else if (!mod && !event.shiftKey && GIZMO_KEYS[key]) s.setGizmo(GIZMO_KEYS[key]);
      else if (!mod && !event.shiftKey && key === 'f') s.requestFrame();
      else handled = false;
      if (handled) event.preventDefault();
    };
    window.addEventListener('keydown', onKeyDown);
    return () => window.removeEventListener('keydown', onKeyDown);
  }, []);
}
