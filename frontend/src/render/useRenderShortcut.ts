import { useEffect, useLayoutEffect, useRef } from 'react';

/**
 * Ctrl/Cmd+Enter renders, from anywhere on the page but a text area (where it applies the JSON
 * tab). In a field, the field gives up the focus first, so that what was typed is committed and
 * rendered, as a click on Render would do.
 */
export function useRenderShortcut(onRender: () => void): void {
  const render = useRef(onRender);
  useLayoutEffect(() => {
    render.current = onRender;
  });
  useEffect(() => {
    const onKeyDown = (event: KeyboardEvent) => {
      if (event.key !== 'Enter' || !(event.ctrlKey || event.metaKey) || event.altKey || event.shiftKey) return;
      const target = event.target as HTMLElement | null;
      if (target?.tagName === 'TEXTAREA') return;
      event.preventDefault();
      if (target?.tagName === 'INPUT' || target?.tagName === 'SELECT') {
        target.blur();
        // the field's commit re-renders the editor with the new scene before the render reads it
        setTimeout(() => render.current(), 0);
      } else {
        render.current();
      }
    };
    window.addEventListener('keydown', onKeyDown);
    return () => window.removeEventListener('keydown', onKeyDown);
  }, []);
}
