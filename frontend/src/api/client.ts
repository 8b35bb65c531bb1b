/**
 * The REST client of the studio: scene examples and the simple render path.
 *
 * Pure TypeScript, no React. Every failure, whether an RFC 9457 problem body, a bare HTTP
 * error or a network failure, comes out as one typed {@link ApiError}.
 */

import { authorizedFetch } from './auth';
import { isRecord } from '../util/json';

/** One entry of `GET /api/scenes`: an example file in `scenes/`, by its file stem. */
export interface SceneSummary {
  name: string;
}

/** One invalid field of a scene, named by its JSON path (`objects[2].radius`). */
export interface FieldError {
  field: string;
  message: string;
}

/** A successful render: the encoded image and what the server told us about it. */
export interface RenderOutput {
  image: Blob;
  /** The response's media type, e.g. `image/png`. */
  contentType: string;
  /** File name for a download, from `Content-Disposition`, else `render.png`/`render.jpg`. */
  filename: string;
  /** `X-Render-Millis`, when the server sent it. */
  renderMillis?: number;
  /** `X-Rays-Per-Second`, when the server sent it. */
  raysPerSecond?: number;
}

/** The media type of an RFC 9457 problem body. */
export const PROBLEM_JSON = 'application/problem+json';

/** A failed request, with what can be shown to the user. */
export class ApiError extends Error {
  /** HTTP status, or 0 when the server could not be reached. */
  readonly status: number;
  readonly title: string;
  readonly detail?: string;
  /** The invalid fields named by a problem body; empty otherwise. */
  readonly errors: FieldError[];

  constructor(status: number, title: string, detail?: string, errors: FieldError[] = []) {
    super(detail ? `${title}: ${detail}` : title);
    this.name = 'ApiError';
    this.status = status;
    this.title = title;
    this.detail = detail;
    this.errors = errors;
  }
}

/** The `fetch` signature the client needs; tests pass their own. */
export type FetchFn = (input: string, init?: RequestInit) => Promise<Response>;

/** The browser's fetch, sending the tab's API key (none with sign-in off): see `auth.ts`. */
const defaultFetch: FetchFn = authorizedFetch();

/** Lists the example scenes. */
export async function fetchSceneList(fetchFn: FetchFn = defaultFetch): Promise<SceneSummary[]> {
  const response = await send(fetchFn, '/api/scenes', { headers: { Accept: 'application/json' } });
  const body: unknown = await response.json();
  if (!Array.isArray(body)) {
    throw new ApiError(response.status, 'Unexpected answer', 'The scene list is not an array');
  }
  return body
    .filter((item): item is SceneSummary => isRecord(item) && typeof item.name === 'string')
    .map((item) => ({ name: item.name }));
}

/** Loads one example scene as parsed JSON. */
export async function fetchScene(name: string, fetchFn: FetchFn = defaultFetch): Promise<unknown> {
  const url = `/api/scenes/${encodeURIComponent(name)}`;
  const response = await send(fetchFn, url, { headers: { Accept: 'application/json' } });
  return response.json();
}

/**
 * The OBJ text of a mesh that ships with the server's example scenes (`GET /api/meshes?file=…`);
 * rejects with an ApiError (a problem body's detail when the server sent one, e.g. 404 for an
 * unknown file).
 */
export async function fetchMeshFile(file: string, fetchFn: FetchFn = defaultFetch, signal?: AbortSignal): Promise<string> {
  const url = `/api/meshes?file=${encodeURIComponent(file)}`;
  const response = await send(fetchFn, url, { headers: { Accept: `text/plain, ${PROBLEM_JSON}` }, signal });
  return response.text();
}

/** Renders a scene given as JSON text; resolves with the image or rejects with an ApiError. */
export async function renderScene(
  sceneJson: string,
  fetchFn: FetchFn = defaultFetch,
  signal?: AbortSignal,
): Promise<RenderOutput> {
  const response = await send(fetchFn, '/api/render', {
    method: 'POST',
    headers: { 'Content-Type': 'application/json', Accept: `image/png, image/jpeg, ${PROBLEM_JSON}` },
    body: sceneJson,
    signal,
  });
  const contentType = mediaType(response.headers.get('Content-Type')) || 'image/png';
  return {
    image: await response.blob(),
    contentType,
    filename: filenameFromDisposition(response.headers.get('Content-Disposition'), contentType),
    renderMillis: numberHeader(response.headers, 'X-Render-Millis'),
    raysPerSecond: numberHeader(response.headers, 'X-Rays-Per-Second'),
  };
}

/** Sends a request; resolves only with a 2xx response, otherwise rejects with an ApiError (the asset client uses it too). */
export async function send(fetchFn: FetchFn, url: string, init: RequestInit): Promise<Response> {
  let response: Response;
  try {
    response = await fetchFn(url, init);
  } catch (cause) {
    if (cause instanceof DOMException && cause.name === 'AbortError') throw cause;
    const message = cause instanceof Error ? cause.message : String(cause);
    throw new ApiError(0, 'Cannot reach the server', message);
  }
  if (!response.ok) throw await toApiError(response);
  return response;
}

/** Turns a non-2xx response into an ApiError, reading a problem body when there is one. */
export async function toApiError(response: Response): Promise<ApiError> {
  if (mediaType(response.headers.get('Content-Type')) === PROBLEM_JSON) {
    try {
      return problemToError(response.status, await response.json());
    } catch {
      // An unreadable problem body: fall through to the status line.
    }
  }
  const title = response.statusText || statusTitle(response.status);
  return new ApiError(response.status, title, statusDetail(response));
}

/** Maps a parsed problem body onto an ApiError; tolerant of missing or odd members. */
export function problemToError(status: number, body: unknown): ApiError {
  const problem = isRecord(body) ? body : {};
  const code = typeof problem.status === 'number' ? problem.status : status;
  const title = typeof problem.title === 'string' ? problem.title : statusTitle(code);
  const detail = typeof problem.detail === 'string' ? problem.detail : undefined;
  const errors = Array.isArray(problem.errors) ? problem.errors.flatMap(toFieldError) : [];
  return new ApiError(code, title, detail, errors);
}

function toFieldError(item: unknown): FieldError[] {
  if (!isRecord(item)) return [];
  const field = firstString(item.field, item.pointer, item.name) ?? '';
  const message = firstString(item.message, item.detail, item.reason) ?? 'is invalid';
  return [{ field, message }];
}

/**
 * The file name of `Content-Disposition: attachment; filename="NAME.png"` (or the RFC 6266
 * `filename*=UTF-8''...` form), without any path; `render.png` (or `.jpg`) when absent.
 */
export function filenameFromDisposition(header: string | null, contentType = 'image/png'): string {
  const fallback = contentType === 'image/jpeg' ? 'render.jpg' : 'render.png';
  if (!header) return fallback;
  const extended = /filename\*\s*=\s*(?:[\w-]+)'[^']*'([^;]+)/i.exec(header);
  const plain = /filename\s*=\s*(?:"((?:[^"\\]|\\.)*)"|([^;]+))/i.exec(header);
  let name: string | undefined;
  if (extended) {
    try {
      name = decodeURIComponent(extended[1].trim());
    } catch {
      name = undefined;
    }
  }
  if (!name && plain) name = (plain[1] ?? plain[2]).replace(/\\(.)/g, '$1').trim();
  const base = name?.split(/[\\/]/).pop()?.trim();
  return base ? base : fallback;
}

/** `image/png; charset=x` → `image/png`, lower case; '' for no header. */
function mediaType(header: string | null): string {
  return (header ?? '').split(';')[0].trim().toLowerCase();
}

function numberHeader(headers: Headers, name: string): number | undefined {
  const raw = headers.get(name);
  if (raw === null || raw.trim() === '') return undefined;
  const value = Number(raw);
  return Number.isFinite(value) ? value : undefined;
}

function statusTitle(status: number): string {
  if (status === 413) return 'Payload Too Large';
  if (status === 429) return 'Too Many Requests';
  if (status === 503) return 'Service Unavailable';
  if (status >= 500) return 'Server error';
  return `HTTP ${status}`;
}

function statusDetail(response: Response): string | undefined {
  const retryAfter = response.headers.get('Retry-After');
  const retry = retryAfter ? ` Try again in ${retryAfter} s.` : ' Try again later.';
  if (response.status === 413) return 'The scene is larger than the server accepts.';
  if (response.status === 429 || response.status === 503) return `The server is busy.${retry}`;
  if (response.status >= 500) return `The server failed (status ${response.status}).`;
  return `The server answered with status ${response.status}.`;
}

function firstString(...values: unknown[]): string | undefined {
  return values.find((v): v is string => typeof v === 'string' && v !== '');
}
