import { useRenderShortcut } from './useRenderShortcut';
import { useCallback, useEffect, useId, useMemo, useState, type ReactNode } from 'react';
import type { FetchFn } from '../api/client';
import type { EventSourceFactory } from '../api/jobs';
import { sameJson } from '../model/sameJson';
import type { Scene } from '../model/types';
import { ErrorSummary, toFieldErrorMap } from './ErrorSummary';
import { fieldWordsOf } from './fieldWordsOf';
import { CompareView } from './history/CompareView';
import { HistoryStrip } from './history/HistoryStrip';
import type { HistoryEntry, RenderHistory } from './history/RenderHistory';
import { recordCaption, sceneOfSent } from './history/renderRecord';
import { sessionRenderHistory } from './history/sessionHistory';
import { useStageHistory } from './history/useStageHistory';
import { ImageViewer } from './ImageViewer';
import { RenderControls } from './RenderControls';
import { RenderNotice } from './RenderNotice';
import { RenderProgress } from './RenderProgress';
import { RenderResult } from './RenderResult';
import { TileCanvas } from './TileCanvas';
import { useRenderJob, type FinishedImage } from './useRenderJob';
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
  /**
   * Fields whose typed text was refused and is not in the scene (JSON path → reason): Render
   * refuses while there are any, and the stage says it does not show the scene as typed.
   */
  unapplied?: Record<string, string>;
  /** Shown at the start of the bar (the stage's tabs). */
  tabs?: ReactNode;
  /** What the stage shows instead of the render (the preview); without it the render is always shown. */
  children?: ReactNode;
  /** True while the stage shows the render rather than `children`. */
  showingRender?: boolean;
  /** Called when the stage should show the render: one starts, or one is picked from the history. */
  onRenderStarted?: () => void;
  /** The render history; by default the page's own, kept in IndexedDB (tests pass a fresh one). */
  history?: RenderHistory;
  /** Puts a render's scene back in the editor; by default the store's `setScene` (one undo step, ids kept). */
  onRestoreScene?: (scene: Scene) => void;
}

/**
 * The stage: a bar with the tabs, Render and Cancel, History and progress, and "Out of date" (a
 * render of a scene that has changed since, with Render again); below it the largest area of the
 * page, showing the preview (`children`) or the render: tiles as they finish, then the image, fitted
 * whole, with its statistics, Download and a full-size viewer. Without a job of its own (after a
 * reload) it shows the last render of the history, until New, Open or an example clears it. The
 * History strip shows any of the last renders, compares two with a slider, or restores a scene.
 */
export function RenderPanel(props: RenderPanelProps) {
  const { scene, onFieldErrors, fetchFn, eventSourceFactory, tabs, children, onRenderStarted } = props;
  const showingRender = children === undefined || props.showingRender === true;
  const history = props.history ?? sessionRenderHistory();
  const render = useRenderJob({ fetchFn, eventSourceFactory, onFinished: history.add });
  const { start, cancel, phase, job, image, error } = render;
  const live = job !== null || phase === 'starting';
  const stage = useStageHistory(history, { live, liveJobId: job?.id ?? null, onShow: onRenderStarted, onRestoreScene: props.onRestoreScene });
  const { shown, single, pair, reset } = stage;
  const [sent, setSent] = useState<{ scene: unknown } | null>(null);
  const [viewing, setViewing] = useState(false);
  const [historyOpen, setHistoryOpen] = useState(false);
  const [refused, setRefused] = useState(false);
  const unapplied = useMemo(() => Object.entries(props.unapplied ?? {}).map(([field, message]) => ({ field, message })), [props.unapplied]);
  useEffect(() => {
    if (unapplied.length === 0) setRefused(false);
  }, [unapplied.length]);
  const stripId = useId();

  const onRender = useCallback(async () => {
    if (unapplied.length > 0) {
      setRefused(true); // nothing is sent: the scene is not what the fields say
      return;
    }
    setRefused(false);
    setSent({ scene });
    reset();
    onRenderStarted?.();
    const outcome = await start(scene);
    if (outcome.kind === 'started') onFieldErrors({}, scene);
    else if (outcome.kind === 'rejected' && outcome.error.status === 400) {
      onFieldErrors(toFieldErrorMap(outcome.error.errors), scene);
    }
  }, [start, scene, onFieldErrors, onRenderStarted, reset, unapplied.length]);

  useRenderShortcut(() => void onRender());

  const current = useMemo(() => (typeof scene === 'string' ? sceneOfSent(scene) : scene), [scene]);
  const shownImage = single ? imageOf(single) : image;
  const outOfDate = pair === null && (single
    ? !sameJson(single.record.scene, current)
    : sent !== null && phase !== 'idle' && phase !== 'starting' && !sameJson(sent.scene, scene));
  const rejected = error?.status === 400 ? error : null;
  const words = fieldWordsOf(sent?.scene);
  return (
    <section className="render-panel stage" aria-label="Render">
      <div className="stage__bar">
        {tabs}
        <RenderControls phase={phase} cancelling={render.cancelling} onRender={() => void onRender()} onCancel={() => void cancel()} />
        <button type="button" aria-expanded={historyOpen} aria-controls={stripId} onClick={() => setHistoryOpen((open) => !open)} title="The last renders: show, compare, restore their scene">
          History{stage.entries.length > 0 ? ` (${stage.entries.length})` : ''}
        </button>
        {phase !== 'idle' && <RenderProgress phase={phase} progress={render.progress} elapsedMillis={render.elapsedMillis} />}
      </div>
      {historyOpen && (
        <HistoryStrip
          id={stripId}
          entries={stage.entries}
          shownId={shown?.record.id ?? null}
          isCurrentScene={(record) => sameJson(record.scene, current)}
          onShow={stage.show}
          onCompare={stage.compare}
          onRestore={stage.restore}
        />
      )}
      {outOfDate && (
        <p className="render-stale" role="status" data-testid="render-out-of-date">
          <strong>Out of date</strong> — the scene has changed since this render.{' '}
          <button type="button" className="small" onClick={() => void onRender()}>
            Render again
          </button>
        </p>
      )}
      {unapplied.length > 0 && (refused ? (
        <ErrorSummary title="Not rendered: fix these fields first" errors={unapplied} {...fieldWordsOf(scene)} />
      ) : (
        <p className="render-stale" role="status" data-testid="not-as-typed">
          <strong>Not as typed</strong> — {unapplied.length === 1 ? 'a field holds' : `${unapplied.length} fields hold`} text
          that is not valid; the views and the live render show the last valid values.
        </p>
      ))}
      {rejected && <ErrorSummary title={rejected.title} detail={rejected.detail} errors={rejected.errors} {...words} />}
      <RenderNotice error={rejected ? null : error} job={job} />
      {children !== undefined && (
        <div className="stage__body" hidden={showingRender}>
          {children}
        </div>
      )}
      <div className="stage__body stage__body--render" hidden={!showingRender} {...(tabs !== undefined ? { role: 'tabpanel', id: 'panel-render', 'aria-labelledby': 'tab-render' } : {})}>
        <TileCanvas canvasRef={render.canvasRef} width={job?.width ?? 0} height={job?.height ?? 0} hidden={!job || image !== null || single !== null || pair !== null} />
        {pair && <CompareView left={sideOf(pair[0])} right={sideOf(pair[1])} onClose={stage.endCompare} />}
        {!pair && shownImage && <RenderResult image={shownImage} stale={outOfDate} caption={shown ? recordCaption(shown.record) : undefined} onViewFullSize={() => setViewing(true)} />}
        {!live && !shownImage && !pair && <p className="placeholder">Press Render to trace the scene; the image appears here.</p>}
      </div>
      {viewing && shownImage && <ImageViewer url={shownImage.url} width={shownImage.width} height={shownImage.height} name={shownImage.filename} onClose={() => setViewing(false)} />}
    </section>
  );
}

/** A render of the history as the stage shows a finished image. */
function imageOf({ record, url }: HistoryEntry): FinishedImage {
  const { filename, width, height, renderMillis, raysPerSecond } = record;
  return { url, filename, width, height, renderMillis, raysPerSecond };
}

/** A render of the history as one side of a comparison. */
function sideOf({ record, url }: HistoryEntry) {
  return { url, width: record.width, height: record.height, label: recordCaption(record) };
}
