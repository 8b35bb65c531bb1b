import { act, renderHook, waitFor } from '@testing-library/react';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import type { FetchFn } from '../api/client';
import { parseJobStatus, type JobStatus } from '../api/jobs';
import { fakeEventSources, statusJson } from '../test/renderFakes';
import { useRenderJob } from './useRenderJob';

function status(overrides: Record<string, unknown> = {}): JobStatus {
  const parsed = parseJobStatus(statusJson(overrides));
  if (!parsed) throw new Error('bad status');
  return parsed;
}

function setup(fetchFn: FetchFn) {
  const streams = fakeEventSources();
  const hook = renderHook(() => useRenderJob({ fetchFn, eventSourceFactory: streams.factory }));
  return { hook, streams };
}

describe('useRenderJob', () => {
  beforeEach(() => {
    let next = 0;
    vi.spyOn(URL, 'createObjectURL').mockImplementation(() => `blob:test/${++next}`);
    vi.spyOn(URL, 'revokeObjectURL').mockImplementation(() => {});
  });
  afterEach(() => {
    vi.useRealTimers();
  });

  it('abandons a start still in flight and cancels the job when it arrives', async () => {
    let answer = (_: Response) => {};
    const fetchFn = vi.fn<FetchFn>((_url, init) => {
      if (init?.method === 'POST') return new Promise<Response>((resolve) => (answer = resolve));
      return Promise.resolve(Response.json(statusJson({ state: 'cancelled' })));
    });
    const { hook, streams } = setup(fetchFn);
    let outcome: Promise<unknown> = Promise.resolve();
    act(() => {
      outcome = hook.result.current.start({ objects: [] });
    });
    await waitFor(() => expect(hook.result.current.phase).toBe('starting'));
    await act(() => hook.result.current.cancel());
    expect(hook.result.current.phase).toBe('idle');

    answer(Response.json(statusJson(), { status: 202 }));
    await expect(outcome).resolves.toEqual({ kind: 'superseded' });
    await waitFor(() => expect(fetchFn).toHaveBeenCalledWith('/api/jobs/k3j', expect.objectContaining({ method: 'DELETE' })));
    expect(streams.opened).toHaveLength(0);
  });

  it('revokes the old image when a new render starts, and cancels a running job on unmount', async () => {
    const fetchFn = vi.fn<FetchFn>(async (url, init) => {
      if (init?.method === 'POST') return Response.json(statusJson(), { status: 202 });
      if (url.endsWith('/image')) return new Response('png', { headers: { 'Content-Type': 'image/png' } });
      return Response.json(statusJson({ state: 'cancelled' }));
    });
    const { hook, streams } = setup(fetchFn);
    await act(() => hook.result.current.start({}));
    act(() => streams.last().emit('end', statusJson({ state: 'done', progress: 1 })));
    await waitFor(() => expect(hook.result.current.image?.url).toBe('blob:test/1'));
    expect(hook.result.current.image?.filename).toBe('still-life.png');

    await act(() => hook.result.current.start({}));
    expect(URL.revokeObjectURL).toHaveBeenCalledWith('blob:test/1');
    expect(hook.result.current.image).toBeNull();
    act(() => streams.last().emit('status', statusJson({ state: 'running' })));

    hook.unmount();
    expect(streams.last().closed).toBe(true);
    expect(fetchFn).toHaveBeenLastCalledWith('/api/jobs/k3j', expect.objectContaining({ method: 'DELETE' }));
  });

  it('keeps the elapsed time counting while running and shows the final figure at the end', async () => {
    vi.useFakeTimers();
    const fetchFn = vi.fn<FetchFn>(async () => Response.json(statusJson(), { status: 202 }));
    const { hook, streams } = setup(fetchFn);
    await act(() => hook.result.current.start({}));
    act(() => streams.last().emit('status', statusJson({ state: 'running', elapsedMillis: 200 })));
    act(() => vi.advanceTimersByTime(1000));
    expect(hook.result.current.elapsedMillis).toBeGreaterThanOrEqual(1100);
    expect(hook.result.current.elapsedMillis).toBeLessThanOrEqual(1200);

    act(() => streams.last().emit('end', statusJson({ state: 'cancelled', elapsedMillis: 1234 })));
    act(() => vi.advanceTimersByTime(1000));
    expect(hook.result.current.elapsedMillis).toBe(1234);
    expect(hook.result.current.job).toEqual(status({ state: 'cancelled', elapsedMillis: 1234 }));
  });

  it('reports a failed cancel and keeps following the job', async () => {
    const fetchFn = vi.fn<FetchFn>(async (_url, init) =>
      init?.method === 'POST'
        ? Response.json(statusJson(), { status: 202 })
        : new Response('', { status: 500, statusText: 'Internal Server Error' }),
    );
    const { hook, streams } = setup(fetchFn);
    await act(() => hook.result.current.start({}));
    await act(() => hook.result.current.cancel());
    expect(hook.result.current.error?.status).toBe(500);
    expect(hook.result.current.cancelling).toBe(false);
    expect(streams.last().closed).toBe(false);
  });

  it('hands each finished render, with the scene it was started for, to onFinished once; a superseded one never', async () => {
    let id = 0;
    let releaseImage = () => {};
    const held = new Promise<void>((resolve) => (releaseImage = resolve));
    const fetchFn = vi.fn<FetchFn>(async (url, init) => {
      if (init?.method === 'POST') return Response.json(statusJson({ id: `job${++id}` }), { status: 202 });
      if (url === '/api/jobs/job1/image') await held;
      if (url.endsWith('/image')) return new Response('png', { headers: { 'Content-Type': 'image/png', 'X-Render-Millis': '1500' } });
      return Response.json(statusJson({ state: 'cancelled' }));
    });
    const onFinished = vi.fn();
    const streams = fakeEventSources();
    const hook = renderHook(() => useRenderJob({ fetchFn, eventSourceFactory: streams.factory, onFinished }));
    const first = { name: 'first', objects: [] };
    const second = { name: 'second', objects: [] };

    await act(() => hook.result.current.start(first));
    act(() => streams.last().emit('end', statusJson({ id: 'job1', state: 'done', progress: 1 })));
    // its image is still on the way when the next render starts: that job's image is never kept
    await act(() => hook.result.current.start(second));
    releaseImage();
    act(() => streams.last().emit('end', statusJson({ id: 'job2', state: 'done', progress: 1, width: 64, height: 32 })));
    await waitFor(() => expect(hook.result.current.image).not.toBeNull());
    expect(onFinished).toHaveBeenCalledTimes(1);
    expect(onFinished).toHaveBeenCalledWith(
      expect.objectContaining({ jobId: 'job2', sentScene: second, width: 64, height: 32, renderMillis: 1500, filename: 'still-life.png' }),
    );
    expect(onFinished.mock.calls[0][0].image).toBeInstanceOf(Blob);
  });
});
