import { useEffect, useRef, useState } from 'react';
import { initialPanels, type Panels } from '../layout';

/** Where the user's choice of panels is kept across reloads. */
export const PANELS_KEY = 'ray-studio.panels';

/** The panels the user last chose, if they chose and the browser kept it. */
function chosenPanels(): Panels | null {
  try {
    const stored = globalThis.localStorage?.getItem(PANELS_KEY);
    if (!stored) return null;
    const { views, inspector } = JSON.parse(stored) as Partial<Panels>;
    return typeof views === 'boolean' && typeof inspector === 'boolean' ? { views, inspector } : null;
  } catch {
    return null;
  }
}

/**
 * The side panels shown: as {@link initialPanels} says for the window's width, following its
 * resizing until the user shows or hides a panel, from then on as the user chose, also after a
 * reload.
 */
export function usePanels(): [Panels, (panels: Panels) => void] {
  const [panels, setPanels] = useState<Panels>(() => chosenPanels() ?? initialPanels(globalThis.innerWidth || 1440));
  const chosen = useRef(chosenPanels() !== null);
  useEffect(() => {
    const onResize = () => {
      if (!chosen.current) setPanels(initialPanels(window.innerWidth));
    };
    window.addEventListener('resize', onResize);
    return () => window.removeEventListener('resize', onResize);
  }, []);
  const choose = (next: Panels) => {
    chosen.current = true;
    setPanels(next);
    try {
      globalThis.localStorage?.setItem(PANELS_KEY, JSON.stringify(next));
    } catch {
      // a browser that keeps nothing: the choice lasts until the reload
    }
  };
  return [panels, choose];
}
