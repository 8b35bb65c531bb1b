import { useState } from 'react';

/** A finished render as the page holds it. */
export interface RenderedImage {
  /** Object URL of the image blob; owned (and revoked) by the caller. */
  url: string;
  /** Name for the Download link. */
  filename: string;
  renderMillis?: number;
  raysPerSecond?: number;
}

/** Props of {@link RenderView}. */
export interface RenderViewProps {
  /** The latest render, or null before the first one. */
  image: RenderedImage | null;
}

/** The result column: the image, its pixel size, render statistics and a Download link. */
export function RenderView({ image }: RenderViewProps) {
  const [size, setSize] = useState<{ url: string; width: number; height: number } | null>(null);
  if (!image) {
    return <p className="placeholder">Render a scene to see the image here.</p>;
  }
  const pixels = size && size.url === image.url ? `${size.width} × ${size.height} px` : null;
  return (
    <figure className="render-view">
      <div className="render-view__frame">
        <img
          src={image.url}
          alt="Rendered scene"
          onLoad={(event) =>
            setSize({
              url: image.url,
              width: event.currentTarget.naturalWidth,
              height: event.currentTarget.naturalHeight,
            })
          }
        />
      </div>
      <figcaption className="render-view__meta">
        {pixels && <span>{pixels}</span>}
        {image.renderMillis !== undefined && <span>{formatMillis(image.renderMillis)}</span>}
        {image.raysPerSecond !== undefined && <span>{formatRate(image.raysPerSecond)}</span>}
        <a className="button" href={image.url} download={image.filename}>
          Download {image.filename}
        </a>
      </figcaption>
    </figure>
  );
}

/** 850 → "850 ms", 12345 → "12.3 s". */
export function formatMillis(millis: number): string {
  return millis < 1000 ? `${Math.round(millis)} ms` : `${(millis / 1000).toFixed(1)} s`;
}

/** 12_300_000 → "12.3 M rays/s". */
export function formatRate(raysPerSecond: number): string {
  const units: [number, string][] = [[1e9, 'G'], [1e6, 'M'], [1e3, 'k']];
  for (const [scale, prefix] of units) {
    if (raysPerSecond >= scale) return `${(raysPerSecond / scale).toFixed(1)} ${prefix} rays/s`;
  }
  return `${Math.round(raysPerSecond)} rays/s`;
}
