/**
 * The sign-in endpoints: who is signed in (`GET /api/me`) and a live view's ticket
 * (`POST /api/preview/tickets`), and the two streams a browser cannot send headers with, made to
 * carry the key when one is set: the live view's WebSocket (with a ticket in its URL) and a job's
 * event stream (read through fetch instead of EventSource).
 */
import { authorizedFetch } from './auth';
import { toApiError, type FetchFn } from './client';
import { isRecord } from '../util/json';

/** What the server knows of the caller. */
export interface Me {
  /** The key's name or the token's subject; '' with sign-in off. */
  principal: string;
  signInRequired: boolean;
}

const signedFetch: FetchFn = authorizedFetch();

/** Asks who is signed in; rejects with an ApiError (401 when the user gave no key). */
export async function fetchMe(fetchFn: FetchFn = signedFetch): Promise<Me> {
  const response = await fetchFn('/api/me', { headers: { Accept: 'application/json' } });
  if (!response.ok) throw await toApiError(response);
  const body: unknown = await response.json();
  const principal = isRecord(body) && typeof body.principal === 'string' ? body.principal : '';
  return { principal, signInRequired: isRecord(body) && body.signInRequired === true };
}

/** A single-use ticket for the live view (about 30 s to use it). */
export async function fetchPreviewTicket(fetchFn: FetchFn = signedFetch): Promise<string> {
  const response = await fetchFn('/api/preview/tickets', { method: 'POST', headers: { Accept: 'application/json' } });
  if (!response.ok) throw await toApiError(response);
  const body: unknown = await response.json();
  if (!isRecord(body) || typeof body.ticket !== 'string') throw new Error('the server sent no ticket');
  return body.ticket;
}

/** `url` with `?ticket=` (or `&ticket=`). */
export function withTicket(url: string, ticket: string): string {
  return `${url}${url.includes('?') ? '&' : '?'}ticket=${encodeURIComponent(ticket)}`;
}
