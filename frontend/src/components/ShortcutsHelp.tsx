import { useEffect, useRef } from 'react';

/** Every keyboard shortcut of the editor, in the words of the help panel. */
export const SHORTCUTS: [string, string][] = [
  ['Ctrl+Z', 'Undo'],
  ['Ctrl+Shift+Z, Ctrl+Y', 'Redo'],
  ['Ctrl+C / Ctrl+V', 'Copy / paste the selection as scene JSON (also between tabs)'],
  ['Shift+click, Ctrl+click', 'Add to the selection, or take out (views, 3D preview, list)'],
  ['Shift+drag', 'Select what lies in a box (top and side views, on empty space)'],
  ['Ctrl+D', 'Duplicate the selection'],
  ['Delete, Backspace', 'Delete the selection'],
  ['Escape', 'Clear the selection; close a menu or this panel'],
  ['W / E / R', 'Move / rotate / scale handles in the 3D preview'],
  ['F', 'Frame the selection (or the whole scene) in the 3D orbit view'],
  ['Arrow keys', 'Nudge the focused thing (or the whole selection it is part of) in a top or side view by one grid step'],
  ['F2', 'Rename the focused object in the list'],
  ['Ctrl+Enter', 'Render (in the JSON tab: apply the JSON)'],
  ['?', 'Show or hide this panel'],
];

/** Props of {@link ShortcutsHelp}. */
export interface ShortcutsHelpProps {
  onClose: () => void;
}

/** The `?` panel: a dialog listing the keyboard shortcuts; Escape, the button or `?` closes it. */
export function ShortcutsHelp({ onClose }: ShortcutsHelpProps) {
  const close = useRef<HTMLButtonElement>(null);
  useEffect(() => {
    close.current?.focus();
    const onKey = (event: KeyboardEvent) => {
      if (event.key === 'Escape') {
        event.preventDefault();
        event.stopPropagation();
        onClose();
      }
    };
    document.addEventListener('keydown', onKey, true);
    return () => document.removeEventListener('keydown', onKey, true);
  }, [onClose]);
  return (
    // Escape (above) is the keyboard's way out; a click on the backdrop is the mouse's
    // eslint-disable-next-line jsx-a11y/click-events-have-key-events, jsx-a11y/no-noninteractive-element-interactions
    <div className="shortcuts-help" role="dialog" aria-modal="true" aria-labelledby="shortcuts-title" onClick={(event) => event.target === event.currentTarget && onClose()}>
      <div className="shortcuts-help__panel">
        <div className="shortcuts-help__header">
          <h2 id="shortcuts-title">Keyboard shortcuts</h2>
          <button ref={close} type="button" className="small" onClick={onClose}>
            Close
          </button>
        </div>
        <dl>
          {SHORTCUTS.map(([keys, what]) => (
            <div key={keys}>
              <dt>
                <kbd>{keys}</kbd>
              </dt>
              <dd>{what}</dd>
            </div>
          ))}
        </dl>
      </div>
    </div>
  );
}
