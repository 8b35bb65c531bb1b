import { useEffect, useRef, useState, type PointerEvent, type WheelEvent } from 'react';
import { actualPixels, fitImage, panBy, zoomAbout, type ViewerView } from './viewerMath';

/** Props of {@link ImageViewer}. */
export interface ImageViewerProps {
  url: string;
  /** The image's size in pixels. */
  width: number;
  height: number;
  /** Its file name, in the title. */
  name: string;
  onClose: () => void;
}

/**
 * The rendered image over the whole window: wheel zooms about the cursor, dragging pans, "1:1"
 * shows one image pixel per device pixel (pixelated, so single pixels can be judged), "Fit" the
 * whole image; Escape or Close ends it.
 */
export function ImageViewer({ url, width, height, name, onClose }: ImageViewerProps) {
  const area = useRef<HTMLDivElement>(null);
  const dpr = globalThis.devicePixelRatio || 1;
  const size = () => ({ w: area.current?.clientWidth || 800, h: area.current?.clientHeight || 600 });
  const [view, setView] = useState<ViewerView>({ scale: 1, x: 0, y: 0 });
  const drag = useRef<{ x: number; y: number } | null>(null);
  const fit = () => {
    const { w, h } = size();
    setView(fitImage(w, h, width, height, dpr));
  };
  // Fit once the area is laid out, and again for another image.
  useEffect(fit, [width, height, dpr]);
  useEffect(() => {
    // Escape is the viewer's alone while it is open (the editor's own Escape clears the selection).
    const onKey = (e: KeyboardEvent) => {
      if (e.key !== 'Escape') return;
      e.stopPropagation();
      onClose();
    };
    window.addEventListener('keydown', onKey, true);
    return () => window.removeEventListener('keydown', onKey, true);
  }, [onClose]);
  const centre = () => ({ x: size().w / 2, y: size().h / 2 });
  const onWheel = (e: WheelEvent) => {
    const r = e.currentTarget.getBoundingClientRect();
    setView((v) => zoomAbout(v, Math.exp(-e.deltaY * 0.002), e.clientX - r.left, e.clientY - r.top));
  };
  const onDown = (e: PointerEvent) => {
    drag.current = { x: e.clientX, y: e.clientY };
    e.currentTarget.setPointerCapture?.(e.pointerId);
  };
  const onMove = (e: PointerEvent) => {
    if (!drag.current) return;
    const dx = e.clientX - drag.current.x, dy = e.clientY - drag.current.y;
    drag.current = { x: e.clientX, y: e.clientY };
    setView((v) => panBy(v, dx, dy));
  };
  const percent = Math.round(view.scale * dpr * 100);
  return (
    <div className="image-viewer" role="dialog" aria-modal="true" aria-label={`Full-size image ${name}`}>
      <div className="image-viewer__bar">
        <strong>{name}</strong>
        <span>{width} × {height} px · {percent}%</span>
        <button type="button" onClick={() => setView((v) => zoomAbout(v, 1 / 1.5, centre().x, centre().y))} aria-label="Zoom out">−</button>
        <button type="button" onClick={() => setView((v) => zoomAbout(v, 1.5, centre().x, centre().y))} aria-label="Zoom in">+</button>
        <button type="button" onClick={() => setView((v) => actualPixels(v, centre().x, centre().y, dpr))} title="One image pixel per screen pixel">1:1</button>
        <button type="button" onClick={fit}>Fit</button>
        <button type="button" onClick={onClose}>Close</button>
      </div>
      <div
        ref={area}
        className="image-viewer__area"
        data-testid="image-viewer-area"
        onWheel={onWheel}
        onPointerDown={onDown}
        onPointerMove={onMove}
        onPointerUp={() => (drag.current = null)}
      >
        <img
          src={url}
          alt="The render at full size"
          draggable={false}
          data-scale={view.scale * dpr}
          style={{ width: width * view.scale, height: height * view.scale, transform: `translate(${view.x}px, ${view.y}px)`, imageRendering: view.scale * dpr >= 2 ? 'pixelated' : 'auto' }}
        />
      </div>
    </div>
  );
}
