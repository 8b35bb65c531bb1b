import { useEffect, useLayoutEffect, useRef } from 'react';
import { copyText } from '../model/clipboard';
import type { GizmoMode } from '../model/gizmo';
import { useSceneStore } from '../store/sceneStore';

/** True when a key press belongs to a text field (the browser's own undo and editing apply). */
function inField(target: EventTarget | null): boolean {
  const el = target as HTMLElement | null;
  if (!el || !el.tagName) return false;
  return el.isContentEditable || ['INPUT', 'TEXTAREA', 'SELECT'].includes(el.tagName);
}

/** True when the user has selected text on the page (Ctrl+C then copies that, as browsers do). */
function hasTextSelection(): boolean {
  const selection = globalThis.getSelection?.();
  return !!selection && !selection.isCollapsed && selection.toString().length > 0;
}

/** W, E, R: the 3D view's move, rotate and scale handles (as in Blender and the three.js editor). */
const GIZMO_KEYS: Record<string, GizmoMode> = { w: 'translate', e: 'rotate', r: 'scale' };

/**
 * Keyboard shortcuts of the editor: Ctrl/Cmd+Z undo, Ctrl/Cmd+Shift+Z and Ctrl+Y redo,
 * Delete/Backspace deletes the selection, Ctrl/Cmd+D duplicates it, Escape clears it; W, E, R pick
 * the 3D handles (move, rotate, scale), F frames the selection in the 3D view; Ctrl/Cmd+C and
 * Ctrl/Cmd+V copy and paste the selection as scene JSON through the system clipboard; `?` calls
 * `onHelp` (the shortcuts panel).
 * Ignored while focus is in an input, so typing is never hijacked.
 */
export function useEditorShortcuts(onHelp?: () => void): void {
  const help = useRef(onHelp);
  useLayoutEffect(() => {
    help.current = onHelp;
  });
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
      else if (mod && key === 'c' && !event.shiftKey && !hasTextSelection()) {
        // Also written here, not only in the copy event: not every browser turns Ctrl+C on a
        // button into a copy event (headless Chromium does not). Writing needs no permission.
        const text = copyText(s.scene, s.selection, s.selectedItems);
        if (text !== null) void navigator.clipboard?.writeText(text).catch(() => {});
        handled = false; // the copy event still follows where the browser sends one
      }
      else if (!mod && (event.key === 'Delete' || event.key === 'Backspace')) s.deleteSelected();
      else if (!mod && event.key === 'Escape') s.select(null);
      else if (!mod && !event.shiftKey && GIZMO_KEYS[key]) s.setGizmo(GIZMO_KEYS[key]);
      else if (!mod && !event.shiftKey && key === 'f') s.requestFrame();
      else if (!mod && event.key === '?' && help.current) help.current();
      else handled = false;
      if (handled) event.preventDefault();
    };
    // Copy and paste go through the system clipboard as scene JSON (so between tabs too): the
    // browser's copy and paste events, which need no permission, outside text fields.
    const onCopy = (event: ClipboardEvent) => {
      if (inField(event.target) || hasTextSelection()) return;
      const s = useSceneStore.getState();
      const text = copyText(s.scene, s.selection, s.selectedItems);
      if (text === null || !event.clipboardData) return;
      event.clipboardData.setData('text/plain', text);
      event.preventDefault();
    };
    const onPaste = (event: ClipboardEvent) => {
      if (inField(event.target)) return;
      const text = event.clipboardData?.getData('text/plain') ?? '';
      if (useSceneStore.getState().pasteText(text)) event.preventDefault();
    };
    window.addEventListener('keydown', onKeyDown);
    document.addEventListener('copy', onCopy);
    document.addEventListener('paste', onPaste);
    return () => {
      window.removeEventListener('keydown', onKeyDown);
      document.removeEventListener('copy', onCopy);
      document.removeEventListener('paste', onPaste);
    };
  }, []);
}
