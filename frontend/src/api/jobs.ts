/**
 * The client of the render-job API: start a job, follow it over server-sent events, cancel it
 * and fetch the finished image.
 *
 * Pure TypeScript, no React. Every failed request comes out as a {@link JobApiError} (an
 * {@link ApiError}, parsed from `application/problem+json` by `client.ts`), which also carries
 * the server's `Retry-After` when it is busy. A request whose `signal` aborts rejects with the
 * abort itself (an `AbortError`), not as an unreachable server.
 */
import {
  ApiError,
  filenameFromDisposition,
  toApiError,
  type FetchFn,
  type RenderOutput,
} from './client';
import { apiKey, authorizedFetch } from './auth';
import { fetchEventSource } from './fetchEventSource';
import { finite, isRecord } from '../util/json';

/** Where a job is in its life; the last three are final. */
export type JobState = 'queued' | 'running' | 'done' | 'failed' | 'cancelled';

/** What `GET /api/jobs/{id}` (and every `status`/`end` event) says about a job. */
export interface JobStatus {
  id: string;
  state: JobState;
  /** Fraction of the image rendered, 0..1. */
  progress: number;
  elapsedMillis: number;
  /** Null until the server has measured it. */
  raysPerSecond: number | null;
  /** Image size in pixels. */
  width: number;
  height: number;
  /** The download's file name, e.g. `still-life.png`. */
  fileName: string;
  mediaType: string;
  /** Why a failed job failed; null otherwise. */
  error: string | null;
}

/** One finished tile of a running job, as a `tile` event carries it. */
export interface JobTile {
  /** Top-left corner and size in image pixels. */
  x: number;
  y: number;
  width: number;
  height: number;
  /** The tile's pixels: a base64-encoded PNG (no `data:` prefix). */
  png: string;
  /** The job's progress once this tile is done, 0..1. */
  progress: number;
}

/** An {@link ApiError} of the job API, with the server's `Retry-After` when it sent one. */
export class JobApiError extends ApiError {
  /** Seconds to wait before trying again (`Retry-After` of a 429/503); undefined otherwise. */
  readonly retryAfter?: number;

  constructor(base: ApiError, retryAfter?: number) {
    super(base.status, base.title, base.detail, base.errors);
    this.name = 'JobApiError';
    this.retryAfter = retryAfter;
  }
}

/** The few members of `EventSource` the client uses; tests pass a fake. */
export interface EventSourceLike {
  readonly readyState: number;
  addEventListener(type: string, listener: (event: MessageEvent) => void): void;
  close(): void;
}

/** Opens an event stream for a URL; the default is `new EventSource(url)`. */
export type EventSourceFactory = (url: string) => EventSourceLike;

/** Callbacks of {@link subscribeJob}; none is called after unsubscribing. */
export interface JobHandlers {
  /** The job's status: first on connecting, then on every change of state. */
  onStatus?: (status: JobStatus) => void;
  /** A finished tile (on a late connection, every tile finished so far comes first). */
  onTile?: (tile: JobTile) => void;
  /** The final status (done, failed or cancelled); the stream is closed before this is called. */
  onEnd?: (status: JobStatus) => void;
  /** The stream broke for good before the end, or sent something unreadable. */
  onError?: (error: ApiError) => void;
}

/** The browser's fetch, sending the tab's API key (none with sign-in off): see `auth.ts`. */
const defaultFetch: FetchFn = authorizedFetch();
/** EventSource cannot send a key: with one set, the stream is read through fetch. */
const defaultEventSource: EventSourceFactory = (url) => (apiKey() ? fetchEventSource(url) : new EventSource(url));
/** `EventSource.CLOSED`, which a fake need not define. */
const CLOSED = 2;

/** The URL of a job, or of one of its sub-resources (`events`, `image`). */
export function jobUrl(id: string, sub?: 'events' | 'image'): string {
  const base = `/api/jobs/${encodeURIComponent(id)}`;
  return sub ? `${base}/${sub}` : base;
}

/**
 * Starts rendering a scene. A string is sent unchanged (the editor's text), anything else as
 * `JSON.stringify` of it. Resolves with the queued job; rejects with a {@link JobApiError}
 * (400 with field errors for an invalid scene, 429 with `retryAfter` when the queue is full).
 */
export async function startJob(sceneJson: unknown, fetchFn: FetchFn = defaultFetch): Promise<JobStatus> {
  const body = typeof sceneJson === 'string' ? sceneJson : JSON.stringify(sceneJson);
  const response = await send(fetchFn, '/api/jobs', {
    method: 'POST',
    headers: { 'Content-Type': 'application/json', Accept: 'application/json' },
    body,
  });
  const location = response.headers.get('Location');
  const fallbackId = location ? decodeURIComponent(location.split('/').filter(Boolean).pop() ?? '') : '';
  return readStatus(response, fallbackId);
}

/** Reads a job's current status; 404 for an unknown id. */
export async function getJob(id: string, fetchFn: FetchFn = defaultFetch, signal?: AbortSignal): Promise<JobStatus> {
  const response = await send(fetchFn, jobUrl(id), { headers: { Accept: 'application/json' }, signal });
  return readStatus(response, id);
}

/** Asks the server to stop a job; resolves with its status (cancelled within one tile's time). */
export async function cancelJob(id: string, fetchFn: FetchFn = defaultFetch, signal?: AbortSignal): Promise<JobStatus> {
  const response = await send(fetchFn, jobUrl(id), {
    method: 'DELETE',
    headers: { Accept: 'application/json' },
    signal,
  });
  return readStatus(response, id);
}

/**
 * Downloads a finished job's image with its file name and statistics; 409 if not done yet. The
 * name comes from `Content-Disposition`, else `fallbackFilename` (the status's `fileName`), else
 * `render.png`/`render.jpg`.
 */
export async function fetchJobImage(
  id: string,
  fetchFn: FetchFn = defaultFetch,
  fallbackFilename?: string,
  signal?: AbortSignal,
): Promise<RenderOutput> {
  const response = await send(fetchFn, jobUrl(id, 'image'), {
    headers: { Accept: 'image/png, image/jpeg, application/problem+json' },
    signal,
  });
  const contentType = (response.headers.get('Content-Type') ?? '').split(';')[0].trim() || 'image/png';
  const disposition = response.headers.get('Content-Disposition');
  return {
    image: await response.blob(),
    contentType,
    filename:
      disposition === null && fallbackFilename
        ? fallbackFilename
        : filenameFromDisposition(disposition, contentType),
    renderMillis: numberHeader(response.headers, 'X-Render-Millis'),
    raysPerSecond: numberHeader(response.headers, 'X-Rays-Per-Second'),
  };
}

/**
 * Follows a job's event stream: `status`, `tile` and `end` events are parsed and handed to the
 * handlers; `end` closes the stream, and so does `signal` when it aborts. Returns a function that
 * closes it early.
 */
export function subscribeJob(
  id: string,
  handlers: JobHandlers,
  eventSourceFactory: EventSourceFactory = defaultEventSource,
  signal?: AbortSignal,
): () => void {
  if (signal?.aborted) return () => undefined;
  const source = eventSourceFactory(jobUrl(id, 'events'));
  let open = true;
  const close = () => {
    open = false;
    signal?.removeEventListener('abort', close);
    source.close();
  };
  signal?.addEventListener('abort', close);

  /** Registers a listener that parses `data` and ignores everything after closing. */
  const on = <T>(type: string, parse: (data: unknown) => T | null, handle: (value: T) => void) => {
    source.addEventListener(type, (event) => {
      if (!open) return;
      const value = parseData(event.data, parse);
      if (value === null) {
        handlers.onError?.(new ApiError(0, 'Unreadable progress event', `The "${type}" event could not be read.`));
        return;
      }
      handle(value);
    });
  };

  on('status', parseJobStatus, (status) => handlers.onStatus?.(status));
  on('tile', parseJobTile, (tile) => handlers.onTile?.(tile));
  on('end', parseJobStatus, (status) => {
    close();
    handlers.onEnd?.(status);
  });
  source.addEventListener('error', () => {
    // While the browser reconnects (readyState CONNECTING) the server replays the tiles;
    // only a stream that gave up is an error.
    if (!open || source.readyState !== CLOSED) return;
    close();
    handlers.onError?.(new ApiError(0, 'Lost the render progress', 'The connection to the server was closed.'));
  });
  return close;
}

/** Reads a JobStatus from JSON, or null when it is not one; optional members get defaults. */
export function parseJobStatus(value: unknown, fallbackId = ''): JobStatus | null {
  if (!isRecord(value)) return null;
  const id = typeof value.id === 'string' && value.id !== '' ? value.id : fallbackId;
  if (!id || !isJobState(value.state)) return null;
  return {
    id,
    state: value.state,
    progress: clamp01(finite(value.progress) ?? (value.state === 'done' ? 1 : 0)),
    elapsedMillis: finite(value.elapsedMillis) ?? 0,
    raysPerSecond: finite(value.raysPerSecond) ?? null,
    width: finite(value.width) ?? 0,
    height: finite(value.height) ?? 0,
    fileName: typeof value.fileName === 'string' ? value.fileName : '',
    mediaType: typeof value.mediaType === 'string' ? value.mediaType : 'image/png',
    error: typeof value.error === 'string' ? value.error : null,
  };
}

/** Reads a JobTile from JSON, or null when it is not one. */
export function parseJobTile(value: unknown): JobTile | null {
  if (!isRecord(value) || typeof value.png !== 'string') return null;
  const [x, y, width, height] = [value.x, value.y, value.width, value.height].map(finite);
  if (x === undefined || y === undefined || width === undefined || height === undefined) return null;
  return { x, y, width, height, png: value.png, progress: clamp01(finite(value.progress) ?? 0) };
}

/** True for the states a job never leaves. */
export function isFinalState(state: JobState): boolean {
  return state === 'done' || state === 'failed' || state === 'cancelled';
}

/**
 * `Retry-After` in seconds from now: either delta-seconds or an HTTP date; undefined when the
 * header is missing or unreadable.
 */
export function parseRetryAfter(header: string | null, now = Date.now()): number | undefined {
  if (header === null || header.trim() === '') return undefined;
  const trimmed = header.trim();
  if (/^\d+$/.test(trimmed)) return Number(trimmed);
  const date = Date.parse(trimmed);
  return Number.isNaN(date) ? undefined : Math.max(0, Math.ceil((date - now) / 1000));
}

/** Sends a request; resolves only with a 2xx response, otherwise rejects with a JobApiError. */
async function send(fetchFn: FetchFn, url: string, init: RequestInit): Promise<Response> {
  let response: Response;
  try {
    response = await fetchFn(url, init);
  } catch (cause) {
    if (init.signal?.aborted) throw cause;
    const message = cause instanceof Error ? cause.message : String(cause);
    throw new JobApiError(new ApiError(0, 'Cannot reach the server', message));
  }
  if (!response.ok) {
    const retryAfter = parseRetryAfter(response.headers.get('Retry-After'));
    throw new JobApiError(await toApiError(response), retryAfter);
  }
  return response;
}

async function readStatus(response: Response, fallbackId: string): Promise<JobStatus> {
  let body: unknown = null;
  try {
    body = await response.json();
  } catch {
    // Handled below as an unexpected answer.
  }
  const status = parseJobStatus(body, fallbackId);
  if (!status) {
    throw new JobApiError(new ApiError(response.status, 'Unexpected answer', 'The server sent no job status.'));
  }
  return status;
}

function parseData<T>(data: unknown, parse: (value: unknown) => T | null): T | null {
  if (typeof data !== 'string') return null;
  try {
    return parse(JSON.parse(data));
  } catch {
    return null;
  }
}

function numberHeader(headers: Headers, name: string): number | undefined {
  const raw = headers.get(name);
  if (raw === null || raw.trim() === '') return undefined;
  const value = Number(raw);
  return Number.isFinite(value) ? value : undefined;
}

function isJobState(value: unknown): value is JobState {
  return value === 'queued' || value === 'running' || value === 'done' || value === 'failed' || value === 'cancelled';
}


function clamp01(value: number): number {
  return Math.min(1, Math.max(0, value));
}
