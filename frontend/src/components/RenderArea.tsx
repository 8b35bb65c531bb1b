import { useState } from 'react';
import { renderScene, type FetchFn } from '../api/client';
import { asApiError } from '../hooks/useSceneExamples';
import { useObjectUrl } from '../hooks/useObjectUrl';
import type { Scene } from '../model/types';
import { ErrorPanel, type DisplayError } from './ErrorPanel';
import { toFieldErrors, type FieldErrors } from './fieldErrors';
import { RenderButton } from './RenderButton';
import { RenderView, type RenderedImage } from './RenderView';

/** Props of {@link RenderArea}; the same contract as the render-job panel's. */
export interface RenderAreaProps {
  /** The scene to render. */
  scene: Scene;
  /** Receives the server's field errors by JSON path (and `{}` when a render starts). */
  onFieldErrors: (errors: FieldErrors) => void;
  /** The fetch for `POST /api/render`; the browser's by default. */
  fetchFn?: FetchFn;
}

/**
 * The simple render path (`POST /api/render`): Render, then the image with its statistics, or
 * the server's problem with a summary of the bad fields (also shown next to their inputs).
 * The fallback used when the render-job panel is not there.
 */
export function RenderArea({ scene, onFieldErrors, fetchFn }: RenderAreaProps) {
  const [error, setError] = useState<DisplayError | null>(null);
  const [rendering, setRendering] = useState(false);
  const [stats, setStats] = useState<Omit<RenderedImage, 'url'> | null>(null);
  const [imageUrl, setImage] = useObjectUrl();

  const render = async () => {
    setError(null);
    onFieldErrors({});
    setRendering(true);
    try {
      const output = await renderScene(JSON.stringify(scene), fetchFn);
      setImage(output.image);
      setStats({ filename: output.filename, renderMillis: output.renderMillis, raysPerSecond: output.raysPerSecond });
    } catch (cause) {
      const apiError = asApiError(cause);
      setError(apiError);
      onFieldErrors(toFieldErrors(apiError.errors));
    } finally {
      setRendering(false);
    }
  };
  const image = imageUrl && stats ? { url: imageUrl, ...stats } : null;
  return (
    <section className="render-area" aria-label="Render">
      <RenderButton rendering={rendering} onRender={() => void render()} />
      <ErrorPanel error={error} />
      <RenderView image={image} />
    </section>
  );
}
