import { useCallback, useState, type ReactNode } from 'react';
import type { FetchFn } from '../api/client';
import type { EventSourceFactory } from '../api/jobs';
import { sameJson } from '../model/sameJson';
import { ErrorSummary, toFieldErrorMap } from './ErrorSummary';
import { fieldWordsOf } from './fieldWordsOf';
import { ImageViewer } from './ImageViewer';
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
  /** Shown at the start of the bar (the stage's tabs). */
  tabs?: ReactNode;
  /** What the stage shows instead of the render (the preview); without it the render is always shown. */
  children?: ReactNode;
  /** True while the stage shows the render rather than `children`. */
  showingRender?: boolean;
  /** Called when a render starts, so the stage can show it. */
  onRenderStarted?: () => void;
}

/**
 * The stage: a bar with the tabs, Render and Cancel, progress and "Out of date" (a render of a
 * scene that has changed since, with Render again); below it the largest area of the page, showing
 * the preview (`children`) or the render: tiles as they finish, then the image, fitted whole, with
 * its statistics, Download and a full-size viewer.
 */
export function RenderPanel(props: RenderPanelProps) {
  const { scene, onFieldErrors, fetchFn, eventSourceFactory, tabs, children, onRenderStarted } = props;
  const showingRender = children === undefined || props.showingRender === true;
  const render = useRenderJob({ fetchFn, eventSourceFactory });
  const { start, cancel, phase, job, image, error } = render;
  const [sent, setSent] = useState<{ scene: unknown } | null>(null);
  const [viewing, setViewing] = useState(false);

  const onRender = useCallback(async () => {
    setSent({ scene });
    onRenderStarted?.();
    const outcome = await start(scene);
    if (outcome.kind === 'started') onFieldErrors({}, scene);
    else if (outcome.kind === 'rejected' && outcome.error.status === 400) {
      onFieldErrors(toFieldErrorMap(outcome.error.errors), scene);
    }
  }, [start, scene, onFieldErrors, onRenderStarted]);

  const rejected = error?.status === 400 ? error : null;
  const outOfDate = sent !== null && phase !== 'idle' && phase !== 'starting' && !sameJson(sent.scene, scene);
  const words = fieldWordsOf(sent?.scene);
  return (
    <section className="render-panel stage" aria-label="Render">
      <div className="stage__bar">
        {tabs}
        <RenderControls phase={phase} cancelling={render.cancelling} onRender={() => void onRender()} onCancel={() => void cancel()} />
        {phase !== 'idle' && <RenderProgress phase={phase} progress={render.progress} elapsedMillis={render.elapsedMillis} />}
      </div>
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
      {children !== undefined && (
        <div className="stage__body" hidden={showingRender}>
          {children}
        </div>
      )}
      <div className="stage__body stage__body--render" hidden={!showingRender}>
        <TileCanvas canvasRef={render.canvasRef} width={job?.width ?? 0} height={job?.height ?? 0} hidden={!job || image !== null} />
        {image && <RenderResult image={image} stale={outOfDate} onViewFullSize={() => setViewing(true)} />}
        {!job && !image && phase === 'idle' && <p className="placeholder">Press Render to trace the scene; the image appears here.</p>}
      </div>
      {viewing && image && <ImageViewer url={image.url} width={image.width} height={image.height} name={image.filename} onClose={() => setViewing(false)} />}
    </section>
  );
}
