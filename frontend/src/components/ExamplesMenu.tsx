import { useEffect, useRef } from 'react';
import type { SceneSummary } from '../api/client';

/** Props of {@link ExamplesMenu}. */
export interface ExamplesMenuProps {
  /** The examples of `GET /api/scenes`. */
  scenes: SceneSummary[];
  loading: boolean;
  /** Called with the picked example's name. */
  onPick: (name: string) => void;
}

/** "Examples ▾": a drop-down gallery of the example scenes in `scenes/`. */
export function ExamplesMenu({ scenes, loading, onPick }: ExamplesMenuProps) {
  const details = useRef<HTMLDetailsElement>(null);
  // A press anywhere else, or Escape, closes the menu, as menus do (Escape hands focus back to its button).
  useEffect(() => {
    const close = (event: PointerEvent) => {
      if (!details.current?.contains(event.target as Node)) details.current?.removeAttribute('open');
    };
    const escape = (event: KeyboardEvent) => {
      const menu = details.current;
      if (event.key !== 'Escape' || !menu?.open) return;
      menu.removeAttribute('open');
      menu.querySelector('summary')?.focus();
      event.preventDefault();
      event.stopPropagation();
    };
    document.addEventListener('pointerdown', close);
    document.addEventListener('keydown', escape, true);
    return () => {
      document.removeEventListener('pointerdown', close);
      document.removeEventListener('keydown', escape, true);
    };
  }, []);
  return (
    <details className="menu" ref={details}>
      <summary className="button" title="Open one of the example scenes (replaces the current scene; Undo brings it back)">
        Examples
      </summary>
      <ul className="menu__list" aria-label="Example scenes">
        {loading && scenes.length === 0 && <li className="hint">Loading examples…</li>}
        {!loading && scenes.length === 0 && <li className="hint">No examples available.</li>}
        {scenes.map((scene) => (
          <li key={scene.name}>
            <button
              type="button"
              onClick={() => {
                details.current?.removeAttribute('open');
                onPick(scene.name);
              }}
            >
              {scene.name}
            </button>
          </li>
        ))}
      </ul>
    </details>
  );
}
