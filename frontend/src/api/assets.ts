/**
 * The asset API: `HEAD /api/assets/{id}` (does the server keep it?), `POST /api/assets` (the raw
 * bytes, with upload progress) and `GET /api/assets/{id}`. Requests carry the tab's API key as the
 * rest of the client does (`auth.ts`); every failure is an {@link ApiError}.
 */
import { authorizedFetch } from './auth';
import { ApiError, PROBLEM_JSON, send, type FetchFn } from './client';
import { isRecord } from '../util/json';

/** What the server answers to an upload. */
export interface AssetInfo {
  id: string;
  bytes: number;
  mediaType: string;
}

const defaultFetch: FetchFn = authorizedFetch();

const assetUrl = (id: string) => `/api/assets/${encodeURIComponent(id)}`;

/** True if the server keeps the asset (200), false if not (404); an ApiError otherwise. */
export async function assetExists(id: string, fetchFn: FetchFn = defaultFetch): Promise<boolean> {
  try {
    await send(fetchFn, assetUrl(id), { method: 'HEAD' });
    return true;
  } catch (error) {
    if (error instanceof ApiError && error.status === 404) return false;
    throw error;
  }
}

/** Uploads the bytes; resolves with the server's id for them (an ApiError for a problem, e.g. 413 or 415). */
export async function uploadAsset(bytes: Blob, mediaType: string, fetchFn: FetchFn = defaultFetch): Promise<AssetInfo> {
  const response = await send(fetchFn, '/api/assets', {
    method: 'POST',
    headers: { 'Content-Type': mediaType, Accept: `application/json, ${PROBLEM_JSON}` },
    body: bytes,
  });
  const body: unknown = await response.json();
  if (!isRecord(body) || typeof body.id !== 'string') throw new ApiError(response.status, 'Unexpected answer', 'The upload was not answered with an asset id');
  return { id: body.id, bytes: Number(body.bytes), mediaType: String(body.mediaType) };
}

/** The asset's bytes. */
export async function fetchAsset(id: string, fetchFn: FetchFn = defaultFetch): Promise<Blob> {
  const response = await send(fetchFn, assetUrl(id), {});
  return response.blob();
}

/**
 * A fetch that reports the upload's progress (XMLHttpRequest: fetch reports none), for large
 * uploads; wrap it in `authorizedFetch` so it sends the key and asks for one on 401.
 */
export function progressFetch(onUpload: (fraction: number) => void): FetchFn {
  if (typeof XMLHttpRequest === 'undefined') return (input, init) => fetch(input, init);
  return (input, init = {}) =>
    new Promise<Response>((resolve, reject) => {
      const xhr = new XMLHttpRequest();
      xhr.open(init.method ?? 'GET', input);
      new Headers(init.headers).forEach((value, name) => xhr.setRequestHeader(name, value));
      xhr.responseType = 'blob';
      xhr.upload.onprogress = (event) => event.lengthComputable && onUpload(event.loaded / event.total);
      xhr.onload = () => {
        const headers = new Headers();
        for (const line of xhr.getAllResponseHeaders().trim().split(/[\r\n]+/)) {
          const at = line.indexOf(':');
          if (at > 0) headers.append(line.slice(0, at).trim(), line.slice(at + 1).trim());
        }
        const body = xhr.status === 204 || xhr.status === 304 ? null : (xhr.response as Blob);
        resolve(new Response(body, { status: xhr.status, statusText: xhr.statusText, headers }));
      };
      xhr.onerror = () => reject(new TypeError('network error'));
      xhr.onabort = () => reject(new DOMException('aborted', 'AbortError'));
      init.signal?.addEventListener('abort', () => xhr.abort());
      xhr.send((init.body ?? null) as XMLHttpRequestBodyInit | null);
    });
}
