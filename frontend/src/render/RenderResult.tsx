import { formatMillis, formatRate } from './format';
import type { FinishedImage } from './useRenderJob';

/** Props of {@link RenderResult}. */
export interface RenderResultProps {
  /** The finished image; its URL is owned by the render hook. */
  image: FinishedImage;
  /** The scene has changed since: the image is dimmed (the panel says so in words). */
  stale?: boolean;
  /** Opens the zoomable full-size viewer; no button without it. */
  onViewFullSize?: () => void;
  /** Which render of the history it is, first in the statistics ("Render 2 · 14:03:12 · 16 spp"). */
  caption?: string;
}

/** The finished image with its size, render time, rays per second and a Download link. */
export function RenderResult({ image, stale = false, onViewFullSize, caption }: RenderResultProps) {
  return (
    <figure className={stale ? 'render-result is-stale' : 'render-result'}>
      <div className="render-frame">
        {/* the View full size button below is the keyboard's way; the click on the image is a shortcut */}
        {/* eslint-disable-next-line jsx-a11y/click-events-have-key-events, jsx-a11y/no-noninteractive-element-interactions */}
        <img
          src={image.url}
          alt="The render"
          title={image.filename}
          width={image.width || undefined}
          height={image.height || undefined}
          data-testid="render-image"
          onClick={onViewFullSize}
          style={onViewFullSize ? { cursor: 'zoom-in' } : undefined}
        />
      </div>
      <figcaption className="render-result__meta" data-testid="render-stats">
        {caption && <span className="render-result__caption">{caption}</span>}
        {image.width > 0 && image.height > 0 && (
          <span>
            {image.width} × {image.height} px
          </span>
        )}
        <span>{formatMillis(image.renderMillis)}</span>
        {image.raysPerSecond !== null && <span>{formatRate(image.raysPerSecond)}</span>}
        {onViewFullSize && (
          <button type="button" onClick={onViewFullSize} title="Open the image at full size: wheel to zoom, drag to pan, 1:1 for one image pixel per screen pixel">
            Full size
          </button>
        )}
        <a className="button" href={image.url} download={image.filename} data-testid="download-link">
          Download {image.filename}
        </a>
      </figcaption>
    </figure>
  );
}
