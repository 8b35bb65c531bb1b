import { useEffect, useRef, useState } from 'react';
import { initialPanels, type Panels } from '../layout';

/**
 * The side panels shown: as {@link initialPanels} says for the window's width, following its
 * resizing until the user shows or hides a panel, from then on as the user chose.
 */
export function usePanels(): [Panels, (panels: Panels) => void] {
  const [panels, setPanels] = useState<Panels>(() => initialPanels(globalThis.innerWidth || 1440));
  const chosen = useRef(false);
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
  };
  return [panels, choose];
}
