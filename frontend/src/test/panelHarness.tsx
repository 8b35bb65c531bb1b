/**
 * The render panel under test: a mock job server and the panel mounted with fakes. Only tests
 * import this file.
 */
import { act, render, screen, waitFor } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { expect, vi } from 'vitest';
import type { FetchFn } from '../api/client';
import { fakeEventSources, MemoryHistoryStorage, statusJson } from './renderFakes';
import { RenderHistory } from '../render/history/RenderHistory';
import { RenderPanel, type RenderPanelProps } from '../render/RenderPanel';

export const SCENE = { name: 'still-life', image: { width: 64, height: 32 }, objects: [{ type: 'sphere' }] };
export const PROBLEM = { 'Content-Type': 'application/problem+json' };
const PNG = new Uint8Array([0x89, 0x50, 0x4e, 0x47]);

export type Handler = (init?: RequestInit) => Response | Promise<Response>;

/** The finished image of any job, as the server sends it. */
function imageResponse(): Response {
  return new Response(PNG, {
    headers: {
      'Content-Type': 'image/png',
      'Content-Disposition': 'attachment; filename="still-life.png"',
      'X-Render-Millis': '1500',
      'X-Rays-Per-Second': '4200000',
    },
  });
}

/**
 * A fetch answering the job routes: every POST starts job `k3j` (or, with `numbered`, job1, job2, …)
 * and every job's image is a PNG; a test overrides any route by "METHOD path".
 */
export function mockServer(routes: Record<string, Handler> = {}, numbered = false) {
  let jobs = 0;
  const defaults: Record<string, Handler> = {
    'POST /api/jobs': () => {
      const id = numbered ? `job${++jobs}` : 'k3j';
      return Response.json(statusJson({ id }), { status: 202, headers: { Location: `/api/jobs/${id}` } });
    },
    'DELETE /api/jobs/k3j': () => Response.json(statusJson({ state: 'running' }), { status: 202 }),
  };
  return vi.fn<FetchFn>(async (url, init) => {
    const key = `${init?.method ?? 'GET'} ${url}`;
    const handler = routes[key] ?? defaults[key] ?? (/^GET \/api\/jobs\/[^/]+\/image$/.test(key) ? imageResponse : undefined);
    return handler ? handler(init) : new Response('', { status: 404 });
  });
}

export function calls(fetchFn: ReturnType<typeof mockServer>, method: string, url: string) {
  return fetchFn.mock.calls.filter(([u, init]) => u === url && (init?.method ?? 'GET') === method);
}

/** A history in memory, as a fresh page has it (`storage` shared: a reload). */
export function freshHistory(storage = new MemoryHistoryStorage()) {
  return new RenderHistory(storage, { makeThumbnail: async () => null });
}

export function setup(fetchFn = mockServer(), history = freshHistory(), scene: unknown = SCENE, more: Partial<RenderPanelProps> = {}) {
  const streams = fakeEventSources();
  const onFieldErrors = vi.fn<(errors: Record<string, string>, scene: unknown) => void>();
  const user = userEvent.setup();
  const panel = (value: unknown) => (
    <RenderPanel scene={value} onFieldErrors={onFieldErrors} fetchFn={fetchFn} eventSourceFactory={streams.factory} history={history} {...more} />
  );
  const view = render(panel(scene));
  /** Clicks Render and waits for the event stream to open. */
  const startRender = async () => {
    const opened = streams.opened.length;
    await user.click(screen.getByTestId('render-button'));
    await waitFor(() => expect(streams.opened.length).toBeGreaterThan(opened));
    return streams.last();
  };
  /** Renders to the end: Render, the job done, its image shown and kept in the history. */
  const renderToEnd = async (id = 'k3j') => {
    const source = await startRender();
    const kept = history.snapshot().entries.length;
    act(() => source.emit('end', statusJson({ id, state: 'done', progress: 1, elapsedMillis: 1500 })));
    await screen.findByTestId('render-image');
    await waitFor(() => expect(history.snapshot().entries.length).toBe(kept + 1));
  };
  /** The panel with another scene, as the editor gives it after an edit. */
  const edit = (value: unknown) => view.rerender(panel(value));
  return { fetchFn, streams, onFieldErrors, user, view, startRender, renderToEnd, edit, history };
}

