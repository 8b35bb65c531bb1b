import { useEffect, useState, type RefObject } from 'react';

/**
 * The element's size in CSS pixels, kept up to date; `fallback` (with `measured: false`) until
 * the browser has laid it out (never, in tests).
 */
export function useElementSize(ref: RefObject<Element | null>, fallback = { width: 480, height: 320 }) {
  const [size, setSize] = useState({ ...fallback, measured: false });
  useEffect(() => {
    const element = ref.current;
    if (!element) return;
    const measure = () => {
      const rect = element.getBoundingClientRect();
      if (rect.width > 0 && rect.height > 0) {
        setSize((old) => (old.width === rect.width && old.height === rect.height ? old : { width: rect.width, height: rect.height, measured: true }));
      }
    };
    measure();
    if (typeof ResizeObserver === 'undefined') return;
    const observer = new ResizeObserver(measure);
    observer.observe(element);
    return () => observer.disconnect();
  }, [ref]);
  return size;
}
