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
} from '../api/jobs';
import type { FinishedRender } from './history/renderRecord';
import type { FinishedImage, RenderPhase } from './renderJobState';
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

/** Manages one render job at a time: start, follow its events, paint tiles, fetch the image. */
export function useRenderJob(options: RenderJobOptions = {}): RenderJob {
  const [job, setJob] = useState<JobStatus | null>(null);
  const [starting, setStarting] = useState(false);
  const [progress, setProgress] = useState(0);
  const [image, setImage] = useState<FinishedImage | null>(null);
  const [error, setError] = useState<JobApiError | null>(null);
  const [cancelling, setCancelling] = useState(false);
  const elapsedMillis = useElapsedClock(job);

  const canvasRef = useRef<HTMLCanvasElement | null>(null);
  const optionsRef = useRef(options);
  const generation = useRef(0); // bumped by every start/abandon; stale callbacks compare it
  const jobRef = useRef<JobStatus | null>(null);
  const unsubscribe = useRef<(() => void) | null>(null);
  const imageUrl = useRef<string | null>(null);
  const sentScene = useRef<unknown>(null); // the scene of the current generation's job

  useEffect(() => {
    optionsRef.current = options;
  });

  const replaceImage = useCallback((next: FinishedImage | null) => {
    if (imageUrl.current) URL.revokeObjectURL(imageUrl.current);
    imageUrl.current = next?.url ?? null;
    setImage(next);
  }, []);

  const stopFollowing = useCallback(() => {
    unsubscribe.current?.();
    unsubscribe.current = null;
  }, []);

  /** Records a status of the current job. */
  const track = useCallback((status: JobStatus) => {
    jobRef.current = status;
    setJob(status);
    setProgress((p) => (status.state === 'done' ? 1 : Math.max(p, status.progress)));
  }, []);

  const finish = useCallback(
    async (status: JobStatus, gen: number) => {
      stopFollowing();
      track(status);
      setCancelling(false);
      if (status.state !== 'done') return;
      const { fetchFn } = optionsRef.current;
      try {
        const out = await fetchJobImage(status.id, fetchFn, status.fileName || undefined);
        if (gen !== generation.current) return;
        const finished = {
          filename: out.filename,
          width: status.width,
          height: status.height,
          renderMillis: out.renderMillis ?? status.elapsedMillis,
          raysPerSecond: out.raysPerSecond ?? status.raysPerSecond,
        };
        replaceImage({ url: URL.createObjectURL(out.image), ...finished });
        optionsRef.current.onFinished?.({ jobId: status.id, finishedAt: Date.now(), sentScene: sentScene.current, image: out.image, ...finished });
      } catch (e) {
        if (gen === generation.current) setError(asJobApiError(e));
      }
    },
    [replaceImage, stopFollowing, track],
  );

  /** The stream gave up: ask once for the job's state, finishing it if it has ended. */
  const recover = useCallback(
    async (id: string, lost: ApiError, gen: number) => {
      try {
        const status = await getJob(id, optionsRef.current.fetchFn);
        if (gen !== generation.current) return;
        if (isFinalState(status.state)) return void (await finish(status, gen));
        track(status);
      } catch {
        // The job's state is unknown; report the lost stream itself.
      }
      if (gen === generation.current) setError(asJobApiError(lost));
    },
    [finish, track],
  );

  const follow = useCallback(
    (status: JobStatus, gen: number) => {
      track(status);
      resetCanvas(canvasRef.current, status.width, status.height);
      if (isFinalState(status.state)) return void finish(status, gen);
      const { eventSourceFactory, decodeTile } = optionsRef.current;
      const current = () => gen === generation.current;
      unsubscribe.current = subscribeJob(
        status.id,
        {
          onStatus: (s) => current() && track(s),
          onTile: (tile) => {
            if (!current()) return;
            setProgress((p) => Math.max(p, tile.progress));
            paintTile(() => canvasRef.current, tile, decodeTile, current).catch(() => undefined);
          },
          onEnd: (s) => current() && void finish(s, gen),
          onError: (e) => current() && void recover(status.id, e, gen),
        },
        eventSourceFactory,
      );
    },
    [finish, recover, track],
  );

  /** Forgets the current job and returns the new generation; cancels the job if under way. */
  const abandon = useCallback(() => {
    const gen = ++generation.current;
    stopFollowing();
    const previous = jobRef.current;
    jobRef.current = null;
    const stopped =
      previous && !isFinalState(previous.state)
        ? cancelJob(previous.id, optionsRef.current.fetchFn).then(() => undefined, () => undefined)
        : Promise.resolve();
    return { gen, stopped };
  }, [stopFollowing]);

  const start = useCallback(
    async (scene: unknown): Promise<StartOutcome> => {
      const { gen, stopped } = abandon();
      sentScene.current = scene;
      replaceImage(null);
      setJob(null);
      setProgress(0);
      setError(null);
      setCancelling(false);
      setStarting(true);
      await stopped; // the old job frees its slot before the new one asks for one
      if (gen !== generation.current) return { kind: 'superseded' };
      const { fetchFn } = optionsRef.current;
      let status: JobStatus;
      try {
        status = await startJob(scene, fetchFn);
      } catch (e) {
        if (gen !== generation.current) return { kind: 'superseded' };
        const rejected = asJobApiError(e);
        setStarting(false);
        setError(rejected);
        return { kind: 'rejected', error: rejected };
      }
      if (gen !== generation.current) {
        // Cancelled or restarted while the POST was in flight: stop the orphan.
        cancelJob(status.id, fetchFn).catch(() => undefined);
        return { kind: 'superseded' };
      }
      setStarting(false);
      follow(status, gen);
      return { kind: 'started', job: status };
    },
    [abandon, follow, replaceImage],
  );

  const cancel = useCallback(async () => {
    const status = jobRef.current;
    if (!status) {
      if (!starting) return;
      generation.current++; // the pending start cancels its job when it arrives
      setStarting(false);
      return;
    }
    if (isFinalState(status.state)) return;
    const gen = generation.current;
    setCancelling(true);
    try {
      const answer = await cancelJob(status.id, optionsRef.current.fetchFn);
      const latest = jobRef.current;
      if (gen !== generation.current || !latest || isFinalState(latest.state)) return;
      if (isFinalState(answer.state)) await finish(answer, gen);
      else track(answer);
    } catch (e) {
      if (gen !== generation.current) return;
      setCancelling(false);
      setError(asJobApiError(e));
    }
  }, [finish, starting, track]);

  useEffect(
    () => () => {
      abandon();
      if (imageUrl.current) URL.revokeObjectURL(imageUrl.current);
      imageUrl.current = null;
    },
    [abandon],
  );

  const phase: RenderPhase = starting ? 'starting' : (job?.state ?? 'idle');
  return { phase, job, progress, elapsedMillis, image, error, cancelling, canvasRef, start, cancel };
}

/** Any thrown value as a JobApiError, so the panel has one type to show. */
function asJobApiError(e: unknown): JobApiError {
  if (e instanceof JobApiError) return e;
  if (e instanceof ApiError) return new JobApiError(e);
  return new JobApiError(new ApiError(0, 'Unexpected error', e instanceof Error ? e.message : String(e)));
}
