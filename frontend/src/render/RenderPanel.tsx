import { useCallback } from 'react';
import type { FetchFn } from '../api/client';
import type { EventSourceFactory } from '../api/jobs';
import { ErrorSummary, toFieldErrorMap } from './ErrorSummary';
import { RenderControls } from './RenderControls';
import { RenderNotice } from './RenderNotice';
import { RenderProgress } from './RenderProgress';
import { RenderResult } from './RenderResult';
import { TileCanvas } from './TileCanvas';
import { useRenderJob } from './useRenderJob';
import './render.css';

/** Props of {@link RenderPanel}. */
export interface RenderPanelProps {
  /** The scene to render: its JSON value, or JSON text (sent unchanged). */
  scene: unknown;
  /**
   * Receives the server's field errors as `{field: message}` (fields by JSON path, e.g.
   * `objects[2].radius`) when it rejects the scene, and `{}` when a later render starts.
   */
  onFieldErrors: (errors: Record<string, string>) => void;
  /** The fetch for the job API; the browser's by default, a mock in tests. */
  fetchFn?: FetchFn;
  /** Opens the progress stream; `new EventSource(url)` by default, a fake in tests. */
  eventSourceFactory?: EventSourceFactory;
}

/**
 * Renders the scene as a server job: Render and Cancel, progress with elapsed time, tiles on a
 * canvas as they finish, then the image with its statistics and a Download link.
 */
export function RenderPanel({ scene, onFieldErrors, fetchFn, eventSourceFactory }: RenderPanelProps) {
  const render = useRenderJob({ fetchFn, eventSourceFactory });
  const { start, cancel, phase, job, image, error } = render;

  const onRender = useCallback(async () => {
    const outcome = await start(scene);
    if (outcome.kind === 'started') onFieldErrors({});
    else if (outcome.kind === 'rejected' && outcome.error.status === 400) {
      onFieldErrors(toFieldErrorMap(outcome.error.errors));
    }
  }, [start, scene, onFieldErrors]);

  const rejected = error?.status === 400 ? error : null;
  return (
    <section className="render-panel" aria-label="Render">
      <RenderControls
        phase={phase}
        cancelling={render.cancelling}
        onRender={() => void onRender()}
        onCancel={() => void cancel()}
      />
      {phase !== 'idle' && (
        <RenderProgress phase={phase} progress={render.progress} elapsedMillis={render.elapsedMillis} />
      )}
      {rejected && <ErrorSummary title={rejected.title} detail={rejected.detail} errors={rejected.errors} />}
      <RenderNotice error={rejected ? null : error} job={job} />
      <TileCanvas
        canvasRef={render.canvasRef}
        width={job?.width ?? 0}
        height={job?.height ?? 0}
        hidden={!job || image !== null}
      />
      {image && <RenderResult image={image} />}
    </section>
  );
}
