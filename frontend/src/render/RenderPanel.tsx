import { useCallback, useState } from 'react';
import type { FetchFn } from '../api/client';
import type { EventSourceFactory } from '../api/jobs';
import { sameJson } from '../model/sameJson';
import { ErrorSummary, toFieldErrorMap } from './ErrorSummary';
import { fieldWordsOf } from './fieldWordsOf';
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
   * `objects[2].radius`) with the scene it refused, and `{}` when a later render starts.
   */
  onFieldErrors: (errors: Record<string, string>, scene: unknown) => void;
  /** The fetch for the job API; the browser's by default, a mock in tests. */
  fetchFn?: FetchFn;
  /** Opens the progress stream; `new EventSource(url)` by default, a fake in tests. */
  eventSourceFactory?: EventSourceFactory;
}

/**
 * Renders the scene as a server job: Render and Cancel, progress with elapsed time, tiles on a
 * canvas as they finish, then the image with its statistics and a Download link. A render of a
 * scene that has changed since says "Out of date" and offers to render again.
 */
export function RenderPanel({ scene, onFieldErrors, fetchFn, eventSourceFactory }: RenderPanelProps) {
  const render = useRenderJob({ fetchFn, eventSourceFactory });
  const { start, cancel, phase, job, image, error } = render;
  const [sent, setSent] = useState<{ scene: unknown } | null>(null);

  const onRender = useCallback(async () => {
    setSent({ scene });
    const outcome = await start(scene);
    if (outcome.kind === 'started') onFieldErrors({}, scene);
    else if (outcome.kind === 'rejected' && outcome.error.status === 400) {
      onFieldErrors(toFieldErrorMap(outcome.error.errors), scene);
    }
  }, [start, scene, onFieldErrors]);

  const rejected = error?.status === 400 ? error : null;
  const outOfDate = sent !== null && phase !== 'idle' && phase !== 'starting' && !sameJson(sent.scene, scene);
  const words = fieldWordsOf(sent?.scene);
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
      {outOfDate && (
        <p className="render-stale" role="status" data-testid="render-out-of-date">
          <strong>Out of date</strong> — the scene has changed since this render.{' '}
          <button type="button" className="small" onClick={() => void onRender()}>
            Render again
          </button>
        </p>
      )}
      {rejected && <ErrorSummary title={rejected.title} detail={rejected.detail} errors={rejected.errors} {...words} />}
      <RenderNotice error={rejected ? null : error} job={job} />
      <TileCanvas
        canvasRef={render.canvasRef}
        width={job?.width ?? 0}
        height={job?.height ?? 0}
        hidden={!job || image !== null}
      />
      {image && <RenderResult image={image} stale={outOfDate} />}
    </section>
  );
}
