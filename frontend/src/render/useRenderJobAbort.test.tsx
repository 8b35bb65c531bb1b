import { act, renderHook, waitFor } from '@testing-library/react';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import type { FetchFn } from '../api/client';
import { fakeEventSources, recordingContext, statusJson, tileJson } from '../test/renderFakes';
import type { DecodedTile, TileDecoder } from './tilePainter';
import { useRenderJob, type StartOutcome } from './useRenderJob';

/** A request the test answers when it likes, with the signal it was sent with. */
interface HeldRequest {
  key: string;
  signal: AbortSignal | undefined;
  answer: (response: Response) => void;
}

/** A fetch that answers nothing by itself: every request waits for the test (and ignores aborts). */
function heldServer() {
  const held: HeldRequest[] = [];
  const fetchFn = vi.fn<FetchFn>(
    (url, init) =>
      new Promise<Response>((answer) => held.push({ key: `${init?.method ?? 'GET'} ${url}`, signal: init?.signal ?? undefined, answer })),
  );
  const keys = () => held.map((request) => request.key);
  /** Waits for the request and takes it off the list. */
  const take = async (key: string): Promise<HeldRequest> => {
    await waitFor(() => expect(keys()).toContain(key));
    return held.splice(keys().indexOf(key), 1)[0];
  };
  return { fetchFn, held, keys, take };
}

const accepted = (id: string) => Response.json(statusJson({ id }), { status: 202 });
const png = () => new Response('png', { headers: { 'Content-Type': 'image/png' } });

function setup(fetchFn: FetchFn, decodeTile?: TileDecoder) {
  const streams = fakeEventSources();
  const onFinished = vi.fn();
  const hook = renderHook(() => useRenderJob({ fetchFn, eventSourceFactory: streams.factory, decodeTile, onFinished }));
  /** Calls start and leaves its outcome pending. */
  const start = (scene: unknown = {}) => {
    let outcome!: Promise<StartOutcome>;
    act(() => {
      outcome = hook.result.current.start(scene);
    });
    return outcome;
  };
  /** Calls cancel and leaves it pending. */
  const cancel = () => {
    let done!: Promise<void>;
    act(() => {
      done = hook.result.current.cancel();
    });
    return done;
  };
  return { hook, streams, onFinished, start, cancel };
}

/** Starts job `id` on a held server and waits until its stream is open. */
async function started(server: ReturnType<typeof heldServer>, job: ReturnType<typeof setup>, id: string) {
  const outcome = job.start();
  const post = await server.take('POST /api/jobs');
  await act(async () => post.answer(accepted(id)));
  await expect(outcome).resolves.toMatchObject({ kind: 'started' });
  return job.streams.last();
}

describe('useRenderJob aborts everything of a job it leaves', () => {
  beforeEach(() => {
    let next = 0;
    vi.spyOn(URL, 'createObjectURL').mockImplementation(() => `blob:test/${++next}`);
    vi.spyOn(URL, 'revokeObjectURL').mockImplementation(() => {});
  });

  it('aborts the image fetch of a job that a new start supersedes, and keeps nothing of its answer', async () => {
    const server = heldServer();
    const job = setup(server.fetchFn);
    const stream = await started(server, job, 'job1');
    act(() => stream.emit('end', statusJson({ id: 'job1', state: 'done', progress: 1 })));
    const image = await server.take('GET /api/jobs/job1/image');
    expect(image.signal?.aborted).toBe(false);

    void job.start();
    expect(image.signal?.aborted).toBe(true);
    await act(async () => image.answer(png()));
    expect(URL.createObjectURL).not.toHaveBeenCalled();
    expect(job.onFinished).not.toHaveBeenCalled();
    expect(job.hook.result.current.phase).toBe('starting');
  });

  it('after unmount, aborts the image fetch and changes nothing when its answer comes', async () => {
    const server = heldServer();
    const job = setup(server.fetchFn);
    const stream = await started(server, job, 'job1');
    act(() => stream.emit('end', statusJson({ id: 'job1', state: 'done', progress: 1 })));
    const image = await server.take('GET /api/jobs/job1/image');

    job.hook.unmount();
    expect(image.signal?.aborted).toBe(true);
    await act(async () => image.answer(png()));
    expect(URL.createObjectURL).not.toHaveBeenCalled();
    expect(job.onFinished).not.toHaveBeenCalled();
  });

  it('revokes the URL of the image shown when it unmounts', async () => {
    const server = heldServer();
    const job = setup(server.fetchFn);
    const stream = await started(server, job, 'job1');
    act(() => stream.emit('end', statusJson({ id: 'job1', state: 'done', progress: 1 })));
    await act(async () => (await server.take('GET /api/jobs/job1/image')).answer(png()));
    expect(job.hook.result.current.image?.url).toBe('blob:test/1');
    expect(URL.revokeObjectURL).not.toHaveBeenCalled();
    job.hook.unmount();
    expect(URL.revokeObjectURL).toHaveBeenCalledWith('blob:test/1');
  });

  it('asks once for the job when its stream is lost, and aborts that question when the job is left', async () => {
    const server = heldServer();
    const job = setup(server.fetchFn);
    const stream = await started(server, job, 'job1');
    act(() => stream.emit('status', statusJson({ id: 'job1', state: 'running', progress: 0.5 })));
    act(() => stream.fail(2));
    const look = await server.take('GET /api/jobs/job1');
    expect(server.keys()).toEqual([]);
    expect(look.signal?.aborted).toBe(false);

    void job.start();
    expect(look.signal?.aborted).toBe(true);
    await act(async () => look.answer(Response.json(statusJson({ id: 'job1', state: 'done', progress: 1 }))));
    expect(job.hook.result.current.phase).toBe('starting');
    expect(job.hook.result.current.error).toBeNull();
    expect(server.keys()).not.toContain('GET /api/jobs/job1/image');
  });

  it('lets nothing of a left job reach the state, even when the new job has the same id', async () => {
    const server = heldServer();
    const job = setup(server.fetchFn);
    const stream = await started(server, job, 'k3j');
    act(() => stream.fail(2));
    const look = await server.take('GET /api/jobs/k3j');

    const again = job.start();
    await act(async () => (await server.take('DELETE /api/jobs/k3j')).answer(Response.json(statusJson({ state: 'cancelled' }))));
    await act(async () => (await server.take('POST /api/jobs')).answer(accepted('k3j')));
    await expect(again).resolves.toMatchObject({ kind: 'started' });
    // the machine cannot tell this answer from one about the new job; the aborted signal can
    await act(async () => look.answer(Response.json(statusJson({ state: 'done', progress: 1 }))));
    expect(job.hook.result.current.phase).toBe('queued');
    expect(job.hook.result.current.progress).toBe(0);
    expect(server.keys()).toEqual([]);
  });

  it('gives a cancel the job’s signal, and still stops the job on the server when a new start aborts it', async () => {
    const server = heldServer();
    const job = setup(server.fetchFn);
    await started(server, job, 'job1');
    void job.cancel();
    const cancel = await server.take('DELETE /api/jobs/job1');
    expect(job.hook.result.current.cancelling).toBe(true);
    expect(cancel.signal?.aborted).toBe(false);

    void job.start();
    expect(cancel.signal?.aborted).toBe(true);
    // the new start's own DELETE of the old job is not aborted with it, and is waited for
    const stop = await server.take('DELETE /api/jobs/job1');
    expect(stop.signal?.aborted ?? false).toBe(false);
    expect(server.keys()).toEqual([]);
    await act(async () => stop.answer(Response.json(statusJson({ id: 'job1', state: 'cancelled' }))));
    await server.take('POST /api/jobs');
  });

  it('lets the second of two starts in flight win, and cancels the job the first one brings', async () => {
    const server = heldServer();
    const job = setup(server.fetchFn);
    const first = job.start({ name: 'first' });
    const firstPost = await server.take('POST /api/jobs');
    const second = job.start({ name: 'second' });
    const secondPost = await server.take('POST /api/jobs');

    await act(async () => secondPost.answer(accepted('job2')));
    await expect(second).resolves.toMatchObject({ kind: 'started', job: { id: 'job2' } });
    await act(async () => firstPost.answer(accepted('job1')));
    await expect(first).resolves.toEqual({ kind: 'superseded' });

    await server.take('DELETE /api/jobs/job1');
    expect(job.streams.opened.map((source) => source.url)).toEqual(['/api/jobs/job2/events']);
    expect(job.hook.result.current.job?.id).toBe('job2');
    expect(job.hook.result.current.phase).toBe('queued');
  });

  it('never aborts the POST: a job the server created for a start abandoned meanwhile is still cancelled', async () => {
    // As a browser's fetch does, the POST rejects when its signal aborts, although the server
    // already has the job: an aborted POST would leave that job running with no one to stop it.
    let created = () => {};
    const fetchFn = vi.fn<FetchFn>((_url, init) => {
      if (init?.method !== 'POST') return Promise.resolve(Response.json(statusJson({ id: 'job1', state: 'cancelled' })));
      return new Promise<Response>((resolve, reject) => {
        init.signal?.addEventListener('abort', () => reject(init.signal?.reason));
        created = () => resolve(accepted('job1'));
      });
    });
    const job = setup(fetchFn);
    const outcome = job.start();
    await waitFor(() => expect(fetchFn).toHaveBeenCalledTimes(1));
    await act(() => job.hook.result.current.cancel());
    created();
    await expect(outcome).resolves.toEqual({ kind: 'superseded' });
    await waitFor(() => expect(fetchFn).toHaveBeenCalledWith('/api/jobs/job1', expect.objectContaining({ method: 'DELETE' })));
  });

  it('paints no tile of a job left while the tile was decoding', async () => {
    const canvas = recordingContext();
    const element = document.createElement('canvas');
    vi.spyOn(element, 'getContext').mockImplementation(() => canvas.context as unknown as ReturnType<HTMLCanvasElement['getContext']>);
    const decoded: Array<(tile: DecodedTile) => void> = [];
    const decodeTile = vi.fn<TileDecoder>(() => new Promise<DecodedTile>((resolve) => decoded.push(resolve)));
    const server = heldServer();
    const job = setup(server.fetchFn, decodeTile);
    job.hook.result.current.canvasRef.current = element;

    const first = await started(server, job, 'job1');
    act(() => first.emit('tile', tileJson(0, 0, 0.5)));
    void job.start();
    await act(async () => decoded[0]({} as DecodedTile));
    expect(canvas.draws).toEqual([]);

    await act(async () => (await server.take('DELETE /api/jobs/job1')).answer(Response.json(statusJson({ id: 'job1', state: 'cancelled' }))));
    await act(async () => (await server.take('POST /api/jobs')).answer(accepted('job2')));
    await waitFor(() => expect(job.streams.opened).toHaveLength(2));
    act(() => job.streams.last().emit('tile', tileJson(32, 0, 0.5)));
    await act(async () => decoded[1]({} as DecodedTile));
    expect(canvas.draws).toEqual([expect.objectContaining({ x: 32, y: 0 })]);
  });

  it('fetches a done job’s image once when both its stream and the answer to a cancel say it is done', async () => {
    const server = heldServer();
    const job = setup(server.fetchFn);
    const stream = await started(server, job, 'job1');
    void job.cancel();
    const cancel = await server.take('DELETE /api/jobs/job1');

    act(() => stream.emit('end', statusJson({ id: 'job1', state: 'done', progress: 1 })));
    const image = await server.take('GET /api/jobs/job1/image');
    await act(async () => cancel.answer(Response.json(statusJson({ id: 'job1', state: 'done', progress: 1 }))));
    await act(async () => image.answer(png()));
    await waitFor(() => expect(job.onFinished).toHaveBeenCalledTimes(1));
    expect(server.keys()).toEqual([]);
    expect(job.hook.result.current.image?.url).toBe('blob:test/1');
    expect(job.hook.result.current.cancelling).toBe(false);
  });
});
