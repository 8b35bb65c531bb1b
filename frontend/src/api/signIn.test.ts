import { describe, expect, it, vi } from 'vitest';
import { fetchEventSource } from './fetchEventSource';
import { fetchMe, fetchPreviewTicket, withTicket } from './signIn';

const json = (body: unknown, status = 200) =>
  new Response(JSON.stringify(body), { status, headers: { 'Content-Type': 'application/json' } });

describe('sign-in endpoints', () => {
  it('reads who is signed in', async () => {
    const fetchFn = vi.fn(async () => json({ principal: 'alice', signInRequired: true }));
    expect(await fetchMe(fetchFn)).toEqual({ principal: 'alice', signInRequired: true });
    expect(fetchFn).toHaveBeenCalledWith('/api/me', expect.anything());
  });

  it('reads sign-in off as nobody needing to sign in', async () => {
    expect(await fetchMe(async () => json({ principal: '', signInRequired: false }))).toEqual({
      principal: '',
      signInRequired: false,
    });
  });

  it('asks for a ticket with POST and passes it in the URL', async () => {
    const fetchFn = vi.fn(async () => json({ ticket: 'abc-_1', expiresInSeconds: 30 }));
    const ticket = await fetchPreviewTicket(fetchFn);
    expect(fetchFn).toHaveBeenCalledWith('/api/preview/tickets', expect.objectContaining({ method: 'POST' }));
    expect(withTicket('ws://host/api/preview', ticket)).toBe('ws://host/api/preview?ticket=abc-_1');
    expect(withTicket('ws://host/api/preview?x=1', 'a+b')).toBe('ws://host/api/preview?x=1&ticket=a%2Bb');
  });

  it('rejects a refused ticket as an ApiError', async () => {
    const refused = new Response(JSON.stringify({ status: 401, title: 'Unauthorized', detail: 'sign in' }), {
      status: 401,
      headers: { 'Content-Type': 'application/problem+json' },
    });
    await expect(fetchPreviewTicket(async () => refused)).rejects.toMatchObject({ status: 401, detail: 'sign in' });
  });
});

describe('fetchEventSource', () => {
  it('parses named events from a stream read through fetch, then ends CLOSED with an error', async () => {
    const text = 'event:status\ndata:{"id":"j","state":"running"}\n\nevent: tile\ndata: {"x":0}\n\n: comment\n\nevent:end\r\ndata:{"a":1}\r\n\r\n';
    const body = new ReadableStream<Uint8Array>({
      start(controller) {
        const bytes = new TextEncoder().encode(text);
        controller.enqueue(bytes.slice(0, 20));
        controller.enqueue(bytes.slice(20));
        controller.close();
      },
    });
    const fetchFn = vi.fn(async (_url: string, _init?: RequestInit) => new Response(body, { headers: { 'Content-Type': 'text/event-stream' } }));
    const source = fetchEventSource('/api/jobs/j/events', fetchFn);
    const seen: string[] = [];
    for (const type of ['status', 'tile', 'end', 'error']) source.addEventListener(type, (e) => seen.push(`${type} ${e.data}`));
    await vi.waitFor(() => expect(seen).toContain('error '));
    expect(seen).toEqual(['status {"id":"j","state":"running"}', 'tile {"x":0}', 'end {"a":1}', 'error ']);
    expect(source.readyState).toBe(2);
    expect(new Headers(fetchFn.mock.calls[0][1]?.headers).get('Accept')).toBe('text/event-stream');
  });

  it('ends with an error when the server refuses the stream', async () => {
    const source = fetchEventSource('/api/jobs/x/events', async () => new Response('', { status: 404 }));
    const error = vi.fn();
    source.addEventListener('error', error);
    await vi.waitFor(() => expect(error).toHaveBeenCalled());
  });
});
