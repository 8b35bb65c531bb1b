import { useCallback, useEffect, useRef, useState, type RefObject } from 'react';
import { ApiError, type FetchFn } from '../api/client';
import {
  JobApiError,
  cancelJob,
  fetchJobImage,
  getJob,
  isFinalState,
  startJob,
  subscribeJob,
  type EventSourceFactory,
  type JobStatus,
  type JobTile,
} from '../api/jobs';
import type { FinishedRender } from './history/renderRecord';
import {
  INITIAL_STATE,
  renderJobReducer,
  viewOf,
  type FinishedImage,
  type RenderJobAction,
  type RenderJobState,
  type RenderPhase,
} from './renderJobState';
import { paintTile, resetCanvas, type TileDecoder } from './tilePainter';
import { useElapsedClock } from './useElapsedClock';

export type { FinishedImage, RenderPhase } from './renderJobState';

/** What {@link RenderJob.start} came to: the caller maps field errors from `rejected`. */
export type StartOutcome =
  | { kind: 'started'; job: JobStatus }
  | { kind: 'rejected'; error: JobApiError }
  | { kind: 'superseded' };

/** Injection points, for tests; each defaults to the browser's own. */
export interface RenderJobOptions {
  fetchFn?: FetchFn;
  eventSourceFactory?: EventSourceFactory;
  decodeTile?: TileDecoder;
  /** Called once for each job that ends done with its image fetched, with the scene it was started for. */
  onFinished?: (render: FinishedRender) => void;
}

/** The state of the current job and what can be done with it. */
export interface RenderJob {
  phase: RenderPhase;
  /** The latest status from the server; null before the first job starts. */
  job: JobStatus | null;
  /** 0..1, advanced by every finished tile. */
  progress: number;
  /** Counts on locally while running; the server's figure once done. */
  elapsedMillis: number;
  image: FinishedImage | null;
  /** The last failed request (start, cancel, image, lost stream); cleared by `start`. */
  error: JobApiError | null;
  /** True between asking to cancel and the job's end. */
  cancelling: boolean;
  /** Attach to the preview canvas: tiles are painted onto it directly, never via state. */
  canvasRef: RefObject<HTMLCanvasElement | null>;
  /** Cancels any job under way, then starts one for the scene. */
  start: (scene: unknown) => Promise<StartOutcome>;
  /** Asks the server to stop the current job (or abandons a start still in flight). */
  cancel: () => Promise<void>;
}

/**
 * One job of the hook: the scene it was started for, and the controller that its requests, its
 * event stream and its tile painting all listen to. Starting another job, cancelling a start still
 * in flight, or unmounting aborts it; from then on nothing of that job reaches the state.
 */
interface JobRun {
  readonly scene: unknown;
  readonly controller: AbortController;
  /** Closes the job's event stream (it closes by itself on abort and after its end event). */
  stopFollowing: () => void;
}

/** A state change: the states before and after an action that was not ignored. */
interface Transition {
  before: RenderJobState;
  after: RenderJobState;
}

const SUPERSEDED: StartOutcome = { kind: 'superseded' };
const ignore = () => undefined;

/**
 * Manages one render job at a time: start, follow its events, paint tiles, fetch the image. What
 * is known of the job is a state machine (`renderJobState.ts`); this hook makes the requests and
 * feeds the machine. The reducer runs here rather than in `useReducer` because the hook acts on
 * its verdict at once: entering the end fetches a done job's image; an ignored action does nothing.
 */
export function useRenderJob(options: RenderJobOptions = {}): RenderJob {
  const [state, setState] = useState<RenderJobState>(INITIAL_STATE);
  const machine = useRef(state); // the state after the latest action: callbacks read this, rendering `state`
  const run = useRef<JobRun | null>(null); // the current job
  const canvasRef = useRef<HTMLCanvasElement | null>(null);
  const optionsRef = useRef(options);
  const view = viewOf(state);
  const elapsedMillis = useElapsedClock(view.job);

  useEffect(() => {
    optionsRef.current = options;
  });

  /** Applies an action of a job; null when the job was left or the machine ignored the action. */
  const dispatch = useCallback((job: JobRun, action: RenderJobAction): Transition | null => {
    if (job.controller.signal.aborted) return null;
    const before = machine.current;
    const after = renderJobReducer(before, action);
    if (after === before) return null;
    machine.current = after;
    setState(after);
    return { before, after };
  }, []);

  /** Fetches a done job's image, shows it and hands it to `onFinished`. */
  const fetchImage = useCallback(
    async (job: JobRun, status: JobStatus) => {
      const { signal } = job.controller;
      try {
        const out = await fetchJobImage(status.id, optionsRef.current.fetchFn, status.fileName || undefined, signal);
        if (signal.aborted) return;
        const finished = {
          filename: out.filename,
          width: status.width,
          height: status.height,
          renderMillis: out.renderMillis ?? status.elapsedMillis,
          raysPerSecond: out.raysPerSecond ?? status.raysPerSecond,
        };
        const url = URL.createObjectURL(out.image);
        if (!dispatch(job, { type: 'imageFetched', jobId: status.id, image: { url, ...finished } })) return URL.revokeObjectURL(url);
        optionsRef.current.onFinished?.({ jobId: status.id, finishedAt: Date.now(), sentScene: job.scene, image: out.image, ...finished });
      } catch (e) {
        dispatch(job, { type: 'imageFailed', jobId: status.id, error: asJobApiError(e) });
      }
    },
    [dispatch],
  );

  /** Applies news of a job; when it ends the job, stops following it and fetches a done job's image. */
  const advance = useCallback(
    (job: JobRun, action: RenderJobAction) => {
      const change = dispatch(job, action);
      if (change?.after.kind !== 'finished' || change.before.kind === 'finished') return;
      job.stopFollowing();
      if (change.after.job.state === 'done') void fetchImage(job, change.after.job);
    },
    [dispatch, fetchImage],
  );

  /** The stream gave up: asks once for the job's state, which ends it or leaves the loss reported. */
  const recover = useCallback(
    async (job: JobRun, jobId: string, lost: ApiError) => {
      let status: JobStatus | null = null;
      try {
        status = await getJob(jobId, optionsRef.current.fetchFn, job.controller.signal);
      } catch {
        // The job's state is unknown; the lost stream itself is reported.
      }
      advance(job, { type: 'streamLost', jobId, error: asJobApiError(lost), status });
    },
    [advance],
  );

  /** Follows an accepted job: its events move the state, its tiles are painted on the canvas. */
  const follow = useCallback(
    (job: JobRun, status: JobStatus) => {
      resetCanvas(canvasRef.current, status.width, status.height);
      advance(job, { type: 'jobAccepted', status });
      if (isFinalState(status.state)) return;
      const { signal } = job.controller;
      const { eventSourceFactory, decodeTile } = optionsRef.current;
      const handlers = {
        onStatus: (s: JobStatus) => advance(job, { type: 'status', status: s }),
        onTile: (tile: JobTile) => {
          advance(job, { type: 'tile', jobId: status.id, progress: tile.progress });
          paintTile(() => canvasRef.current, tile, decodeTile, () => !signal.aborted).catch(ignore);
        },
        onEnd: (s: JobStatus) => advance(job, { type: 'ended', status: s }),
        onError: (lost: ApiError) => void recover(job, status.id, lost),
      };
      job.stopFollowing = subscribeJob(status.id, handlers, eventSourceFactory, signal);
    },
    [advance, recover],
  );

  /** Leaves the current job: aborts everything of it, and stops it on the server if under way. */
  const abandon = useCallback((): Promise<void> => {
    const left = machine.current;
    run.current?.controller.abort();
    run.current = null;
    if (left.kind !== 'following' && left.kind !== 'cancelling') return Promise.resolve();
    // Without the job's signal: this request is meant to outlive it.
    return cancelJob(left.job.id, optionsRef.current.fetchFn).then(ignore, ignore);
  }, []);

  const start = useCallback(
    async (scene: unknown): Promise<StartOutcome> => {
      const stopped = abandon();
      const job: JobRun = { scene, controller: new AbortController(), stopFollowing: ignore };
      run.current = job;
      dispatch(job, { type: 'startRequested' });
      await stopped; // the old job frees its slot before the new one asks for one
      const { signal } = job.controller;
      if (signal.aborted) return SUPERSEDED;
      const { fetchFn } = optionsRef.current;
      let status: JobStatus;
      try {
        // Not given the signal: a POST aborted after the server took it would leave a job running
        // that no one knows to stop. Its answer is awaited, and its job cancelled if left meanwhile.
        status = await startJob(scene, fetchFn);
      } catch (e) {
        if (signal.aborted) return SUPERSEDED;
        const error = asJobApiError(e);
        dispatch(job, { type: 'startRejected', error });
        return { kind: 'rejected', error };
      }
      if (signal.aborted) {
        cancelJob(status.id, fetchFn).catch(ignore);
        return SUPERSEDED;
      }
      follow(job, status);
      return { kind: 'started', job: status };
    },
    [abandon, dispatch, follow],
  );

  const cancel = useCallback(async () => {
    const job = run.current;
    const change = job ? dispatch(job, { type: 'cancelRequested' }) : null;
    if (!job || !change) return;
    // A start still in flight is left; its job is cancelled when the POST answers.
    if (change.after.kind !== 'cancelling') return void abandon();
    const jobId = change.after.job.id;
    try {
      const answer = await cancelJob(jobId, optionsRef.current.fetchFn, job.controller.signal);
      advance(job, { type: 'cancelAnswered', status: answer });
    } catch (e) {
      dispatch(job, { type: 'cancelFailed', jobId, error: asJobApiError(e) });
    }
  }, [abandon, advance, dispatch]);

  useEffect(() => () => void abandon(), [abandon]);

  // Every image URL is revoked once the state no longer shows it: replaced, cleared or unmounted.
  const imageUrl = view.image?.url;
  useEffect(() => (imageUrl ? () => URL.revokeObjectURL(imageUrl) : undefined), [imageUrl]);

  return { ...view, elapsedMillis, canvasRef, start, cancel };
}

/** Any thrown value as a JobApiError, so the panel has one type to show. */
function asJobApiError(e: unknown): JobApiError {
  if (e instanceof JobApiError) return e;
  if (e instanceof ApiError) return new JobApiError(e);
  return new JobApiError(new ApiError(0, 'Unexpected error', e instanceof Error ? e.message : String(e)));
}
