import { describe, expect, it, vi } from 'vitest';
import { fakeEventSources, statusJson, tileJson } from '../test/renderFakes';
import { ApiError, type FetchFn } from './client';
import {
  JobApiError,
  cancelJob,
  fetchJobImage,
  getJob,
  parseJobStatus,
  parseRetryAfter,
  startJob,
  subscribeJob,
  type JobHandlers,
} from './jobs';

const PROBLEM = { 'Content-Type': 'application/problem+json' };

function answering(response: Response) {
  return vi.fn<FetchFn>(async () => response);
}

function accepted(body: Record<string, unknown>, location = '/api/jobs/k3j') {
  return new Response(JSON.stringify(body), {
    status: 202,
    headers: { 'Content-Type': 'application/json', Location: location },
  });
}

async function rejectionOf(promise: Promise<unknown>): Promise<JobApiError> {
  const error = await promise.then(
    () => {
      throw new Error('expected the promise to reject');
    },
    (e: unknown) => e,
  );
  expect(error).toBeInstanceOf(JobApiError);
  expect(error).toBeInstanceOf(ApiError);
  return error as JobApiError;
}

describe('startJob', () => {
  it('posts the scene as JSON and reads the 202 status', async () => {
    const fetchFn = answering(accepted(statusJson({ raysPerSecond: 4.2e6, elapsedMillis: 12 })));
    const scene = { name: 'still-life', objects: [{ type: 'sphere' }] };
    const status = await startJob(scene, fetchFn);
    const [url, init] = fetchFn.mock.calls[0];
    expect(url).toBe('/api/jobs');
    expect(init?.method).toBe('POST');
    expect(new Headers(init?.headers).get('Content-Type')).toBe('application/json');
    expect(JSON.parse(String(init?.body))).toEqual(scene);
    expect(status).toEqual({
      id: 'k3j',
      state: 'queued',
      progress: 0,
      elapsedMillis: 12,
      raysPerSecond: 4.2e6,
      width: 64,
      height: 32,
      fileName: 'still-life.png',
      mediaType: 'image/png',
      error: null,
    });
  });

  it('sends scene text unchanged', async () => {
    const fetchFn = answering(accepted(statusJson()));
    const text = '{ "objects": [] }';
    await startJob(text, fetchFn);
    expect(fetchFn.mock.calls[0][1]?.body).toBe(text);
  });

  it('takes the id from Location when the body has none', async () => {
    const fetchFn = answering(accepted(statusJson({ id: undefined }), '/api/jobs/from-location'));
    expect((await startJob({}, fetchFn)).id).toBe('from-location');
  });

  it('rejects an invalid scene with the field errors of the problem body', async () => {
    const problem = {
      title: 'Invalid scene',
      status: 400,
      detail: '2 problems',
      errors: [
        { field: 'objects[0].radius', message: 'must be greater than 0' },
        { field: 'camera.up', message: 'must not be a zero-length vector' },
      ],
    };
    const fetchFn = answering(new Response(JSON.stringify(problem), { status: 400, headers: PROBLEM }));
    const error = await rejectionOf(startJob({}, fetchFn));
    expect(error.status).toBe(400);
    expect(error.title).toBe('Invalid scene');
    expect(error.errors).toEqual(problem.errors);
    expect(error.retryAfter).toBeUndefined();
  });

  it('exposes Retry-After in seconds when the queue is full', async () => {
    const problem = { title: 'Too Many Requests', status: 429, detail: 'The render queue is full' };
    const fetchFn = answering(
      new Response(JSON.stringify(problem), { status: 429, headers: { ...PROBLEM, 'Retry-After': '7' } }),
    );
    const error = await rejectionOf(startJob({}, fetchFn));
    expect(error.status).toBe(429);
    expect(error.retryAfter).toBe(7);
    expect(error.detail).toBe('The render queue is full');
  });

  it('reports an unreachable server as status 0', async () => {
    const fetchFn = vi.fn<FetchFn>(async () => {
      throw new TypeError('Failed to fetch');
    });
    const error = await rejectionOf(startJob({}, fetchFn));
    expect(error.status).toBe(0);
    expect(error.detail).toBe('Failed to fetch');
  });

  it('refuses a 2xx answer that is not a job status', async () => {
    const fetchFn = answering(new Response('{"hello":1}', { status: 202 }));
    expect((await rejectionOf(startJob({}, fetchFn))).title).toBe('Unexpected answer');
  });
});

describe('parseRetryAfter', () => {
  it('reads delta-seconds and HTTP dates', () => {
    const now = Date.parse('2025-01-01T00:00:00Z');
    expect(parseRetryAfter('120', now)).toBe(120);
    expect(parseRetryAfter('Wed, 01 Jan 2025 00:00:30 GMT', now)).toBe(30);
    expect(parseRetryAfter('Tue, 31 Dec 2024 23:00:00 GMT', now)).toBe(0);
    expect(parseRetryAfter(null, now)).toBeUndefined();
    expect(parseRetryAfter('soon', now)).toBeUndefined();
  });
});

describe('getJob, cancelJob and fetchJobImage', () => {
  it('reads a job by id', async () => {
    const fetchFn = answering(Response.json(statusJson({ state: 'running', progress: 0.5 })));
    const status = await getJob('k3j', fetchFn);
    expect(fetchFn.mock.calls[0][0]).toBe('/api/jobs/k3j');
    expect(status.state).toBe('running');
    expect(status.progress).toBe(0.5);
  });

  it('rejects an unknown id with 404', async () => {
    const problem = { title: 'Not Found', status: 404, detail: 'No job abc' };
    const fetchFn = answering(new Response(JSON.stringify(problem), { status: 404, headers: PROBLEM }));
    const error = await rejectionOf(getJob('abc', fetchFn));
    expect(error.status).toBe(404);
    expect(error.detail).toBe('No job abc');
  });

  it('cancels with DELETE and reads the answer', async () => {
    const fetchFn = answering(Response.json(statusJson({ state: 'running' }), { status: 202 }));
    const status = await cancelJob('k3j', fetchFn);
    const [url, init] = fetchFn.mock.calls[0];
    expect(url).toBe('/api/jobs/k3j');
    expect(init?.method).toBe('DELETE');
    expect(status.state).toBe('running');
  });

  it('encodes the id into the URL', async () => {
    const fetchFn = answering(Response.json(statusJson({ id: 'a/b' })));
    await cancelJob('a/b', fetchFn);
    expect(fetchFn.mock.calls[0][0]).toBe('/api/jobs/a%2Fb');
  });

  it('downloads the image with its file name and statistics', async () => {
    const bytes = new Uint8Array([0x89, 0x50, 0x4e, 0x47]);
    const fetchFn = answering(
      new Response(bytes, {
        headers: {
          'Content-Type': 'image/png',
          'Content-Disposition': 'attachment; filename="still-life.png"',
          'X-Render-Millis': '1234',
          'X-Rays-Per-Second': '4200000',
        },
      }),
    );
    const output = await fetchJobImage('k3j', fetchFn);
    expect(fetchFn.mock.calls[0][0]).toBe('/api/jobs/k3j/image');
    expect(output.filename).toBe('still-life.png');
    expect(output.contentType).toBe('image/png');
    expect(output.renderMillis).toBe(1234);
    expect(output.raysPerSecond).toBe(4_200_000);
    expect(new Uint8Array(await output.image.arrayBuffer())).toEqual(bytes);
  });

  it('falls back to the status file name without Content-Disposition', async () => {
    const fetchFn = answering(new Response('x', { headers: { 'Content-Type': 'image/jpeg' } }));
    expect((await fetchJobImage('k3j', fetchFn, 'glass.jpg')).filename).toBe('glass.jpg');
  });

  it('hands the signal to every request, so the caller can abort it', async () => {
    const { signal } = new AbortController();
    const fetchFn = vi.fn<FetchFn>(async (url) =>
      url.endsWith('/image') ? new Response('png') : Response.json(statusJson()),
    );
    await getJob('k3j', fetchFn, signal);
    await cancelJob('k3j', fetchFn, signal);
    await fetchJobImage('k3j', fetchFn, undefined, signal);
    expect(fetchFn.mock.calls.map(([, init]) => init?.signal)).toEqual([signal, signal, signal]);
  });

  it('rejects an aborted request with the abort itself, not as an unreachable server', async () => {
    const controller = new AbortController();
    // as the browser's fetch does: pending until the signal aborts, then rejects with its reason
    const fetchFn = vi.fn<FetchFn>(
      (_url, init) => new Promise<Response>((_, reject) => init?.signal?.addEventListener('abort', () => reject(init.signal?.reason))),
    );
    const pending = getJob('k3j', fetchFn, controller.signal);
    controller.abort();
    const error = await pending.catch((e: unknown) => e);
    expect(error).not.toBeInstanceOf(ApiError);
    expect(error).toHaveProperty('name', 'AbortError');
  });

  it('rejects an image that is not ready with 409', async () => {
    const problem = { title: 'Conflict', status: 409, detail: 'The job is still running' };
    const fetchFn = answering(new Response(JSON.stringify(problem), { status: 409, headers: PROBLEM }));
    expect((await rejectionOf(fetchJobImage('k3j', fetchFn))).status).toBe(409);
  });
});

describe('parseJobStatus', () => {
  it('refuses anything without an id and a known state', () => {
    expect(parseJobStatus(null)).toBeNull();
    expect(parseJobStatus({ id: 'a', state: 'sleeping' })).toBeNull();
    expect(parseJobStatus({ state: 'done' })).toBeNull();
  });

  it('fills in missing members and clamps progress', () => {
    const status = parseJobStatus({ id: 'a', state: 'running', progress: 1.5, raysPerSecond: 'fast' });
    expect(status).toMatchObject({ progress: 1, raysPerSecond: null, elapsedMillis: 0, error: null });
  });
});

describe('subscribeJob', () => {
  function subscribed() {
    const streams = fakeEventSources();
    const handlers = {
      onStatus: vi.fn<NonNullable<JobHandlers['onStatus']>>(),
      onTile: vi.fn<NonNullable<JobHandlers['onTile']>>(),
      onEnd: vi.fn<NonNullable<JobHandlers['onEnd']>>(),
      onError: vi.fn<NonNullable<JobHandlers['onError']>>(),
    };
    const unsubscribe = subscribeJob('k3j', handlers, streams.factory);
    return { source: streams.last(), handlers, unsubscribe };
  }

  it('opens the job event stream', () => {
    expect(subscribed().source.url).toBe('/api/jobs/k3j/events');
  });

  it('parses status, tile and end events and hands each to its handler', () => {
    const { source, handlers } = subscribed();
    source.emit('status', statusJson({ state: 'running' }));
    source.emit('tile', tileJson(32, 0, 0.5));
    source.emit('end', statusJson({ state: 'done', progress: 1, elapsedMillis: 900, raysPerSecond: 2e6 }));

    expect(handlers.onStatus).toHaveBeenCalledTimes(1);
    expect(handlers.onStatus.mock.calls[0][0].state).toBe('running');
    expect(handlers.onTile).toHaveBeenCalledWith({
      x: 32,
      y: 0,
      width: 32,
      height: 32,
      png: btoa('\x89PNG tile'),
      progress: 0.5,
    });
    expect(handlers.onEnd).toHaveBeenCalledTimes(1);
    expect(handlers.onEnd.mock.calls[0][0]).toMatchObject({ state: 'done', elapsedMillis: 900, raysPerSecond: 2e6 });
    expect(handlers.onError).not.toHaveBeenCalled();
  });

  it('closes the stream on end and ignores anything after it', () => {
    const { source, handlers } = subscribed();
    source.emit('end', statusJson({ state: 'cancelled' }));
    expect(source.closed).toBe(true);
    source.emit('tile', tileJson(0, 0, 0.1));
    source.fail(2);
    expect(handlers.onTile).not.toHaveBeenCalled();
    expect(handlers.onError).not.toHaveBeenCalled();
  });

  it('closes the stream when unsubscribed', () => {
    const { source, handlers, unsubscribe } = subscribed();
    unsubscribe();
    expect(source.closed).toBe(true);
    source.emit('status', statusJson());
    expect(handlers.onStatus).not.toHaveBeenCalled();
  });

  it('closes the stream when its signal aborts and calls no handler after it', () => {
    const streams = fakeEventSources();
    const onStatus = vi.fn();
    const controller = new AbortController();
    subscribeJob('k3j', { onStatus }, streams.factory, controller.signal);
    controller.abort();
    expect(streams.last().closed).toBe(true);
    streams.last().emit('status', statusJson());
    expect(onStatus).not.toHaveBeenCalled();
  });

  it('opens no stream for a signal already aborted', () => {
    const streams = fakeEventSources();
    subscribeJob('k3j', {}, streams.factory, AbortSignal.abort());
    expect(streams.opened).toHaveLength(0);
  });

  it('reports an unreadable event without closing the stream', () => {
    const { source, handlers } = subscribed();
    source.emit('tile', 'not json');
    source.emit('status', { id: 'k3j' });
    expect(handlers.onError).toHaveBeenCalledTimes(2);
    expect(source.closed).toBe(false);
  });

  it('waits while the browser reconnects and reports a stream that gave up', () => {
    const { source, handlers } = subscribed();
    source.fail(0);
    expect(handlers.onError).not.toHaveBeenCalled();
    source.fail(2);
    expect(handlers.onError).toHaveBeenCalledTimes(1);
    expect(handlers.onError.mock.calls[0][0]).toBeInstanceOf(ApiError);
  });
});
