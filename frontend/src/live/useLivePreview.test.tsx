import { act, renderHook } from '@testing-library/react';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { recordingContext } from '../test/renderFakes';
import { fakeSockets, instantDecoder, manualDecoder } from '../test/liveFakes';
import type { ImageDecoder } from './framePainter';
import { RETRY_DELAYS } from './liveSession';
import { useLivePreview, type LivePreviewOptions } from './useLivePreview';

const SCENE = { objects: [{ type: 'sphere', center: [0, 1, 0], radius: 1 }] };
const moved = (x: number) => ({ objects: [{ type: 'sphere', center: [x, 1, 0], radius: 1 }] });

function setup(decodeImage: ImageDecoder = instantDecoder, props: Partial<LivePreviewOptions> = {}) {
  const sockets = fakeSockets();
  const drawing = recordingContext();
  vi.spyOn(HTMLCanvasElement.prototype, 'getContext').mockReturnValue(drawing.context as never);
  const onFieldErrors = vi.fn();
  const hook = renderHook((p: Partial<LivePreviewOptions>) => useLivePreview({ scene: SCENE, width: 64, height: 48, onFieldErrors, socketFactory: sockets.factory, decodeImage, url: 'ws://test/api/preview', ...p }), {
    initialProps: props,
  });
  const canvas = document.createElement('canvas');
  hook.result.current.canvasRef.current = canvas;
  return { hook, sockets, drawing, canvas, onFieldErrors };
}

/** Runs the next animation frame (where the view sends), then lets decodes finish. */
async function nextFrame() {
  await act(async () => {
    vi.advanceTimersToNextFrame();
  });
}

/** Lets pending promises (image decodes) settle. */
const settle = () => act(async () => {});

describe('useLivePreview', () => {
  beforeEach(() => {
    vi.useFakeTimers({ toFake: ['setTimeout', 'clearTimeout', 'requestAnimationFrame', 'cancelAnimationFrame'] });
  });
  afterEach(() => {
    vi.useRealTimers();
  });

  it('opens its socket while mounted, sends the scene at the view size once open, and closes on unmount', async () => {
    const { hook, sockets } = setup();
    expect(sockets.opened).toHaveLength(1);
    const socket = sockets.last();
    expect(socket.url).toBe('ws://test/api/preview');
    expect(socket.binaryType).toBe('arraybuffer');
    expect(hook.result.current.connection.state).toBe('connecting');
    await nextFrame();
    expect(socket.sent).toEqual([]); // nothing before the upgrade

    act(() => socket.open());
    await nextFrame();
    expect(socket.messages()).toEqual([{ revision: 1, scene: SCENE, width: 64, height: 48 }]);
    expect(hook.result.current.connection.state).toBe('open');
    expect(hook.result.current.sentRevision).toBe(1);

    hook.unmount();
    expect(socket.closedBy).toEqual({ code: 1000, reason: 'view closed' });
  });

  it('sends at most one revision per animation frame, always the newest, with increasing revisions', async () => {
    const { hook, sockets } = setup();
    act(() => sockets.last().open());
    await nextFrame();
    for (const x of [1, 2, 3]) hook.rerender({ scene: moved(x) });
    expect(sockets.last().sent).toHaveLength(1);
    await nextFrame();
    hook.rerender({ scene: moved(4) });
    await nextFrame();
    expect(sockets.last().revisions().map((m) => [m.revision, (m.scene as typeof SCENE).objects[0].center[0]])).toEqual([
      [1, 0],
      [2, 3],
      [3, 4],
    ]);
  });

  it('sends no revision for an equal scene (a drag committed where its preview left it), but does for a new size', async () => {
    const { hook, sockets } = setup();
    act(() => sockets.last().open());
    await nextFrame();
    hook.rerender({ scene: structuredClone(SCENE) });
    await nextFrame();
    hook.rerender({ scene: moved(1) }); // moved and back within one frame
    hook.rerender({ scene: structuredClone(SCENE) });
    await nextFrame();
    expect(sockets.last().sent).toHaveLength(1);
    hook.rerender({ scene: structuredClone(SCENE), width: 128, height: 96 });
    await nextFrame();
    expect(sockets.last().revisions()[1]).toEqual({ revision: 2, scene: SCENE, width: 128, height: 96 });
  });

  it('holds revisions while the socket is still sending one, then sends only the newest', async () => {
    const { hook, sockets } = setup();
    const socket = sockets.last();
    act(() => socket.open());
    await nextFrame();
    socket.bufferedAmount = 5000;
    hook.rerender({ scene: moved(1) });
    await nextFrame();
    hook.rerender({ scene: moved(2) });
    await nextFrame();
    expect(socket.sent).toHaveLength(1);
    socket.bufferedAmount = 0;
    await nextFrame();
    expect(socket.messages().map((m) => m.revision)).toEqual([1, 2]);
    expect(socket.revisions()[1].scene).toEqual(moved(2));
  });

  it('draws each frame scaled to the view and reports its header', async () => {
    const { hook, sockets, drawing, canvas } = setup();
    const socket = sockets.last();
    act(() => socket.open());
    await nextFrame();
    act(() => socket.frame({ revision: 1, pass: 1, width: 8, height: 6 }));
    await settle();
    expect(drawing.draws).toEqual([expect.objectContaining({ x: 0, y: 0, width: 64, height: 48 })]);
    expect([canvas.width, canvas.height]).toEqual([64, 48]);
    expect(hook.result.current.frame).toMatchObject({ revision: 1, pass: 1, width: 8 });
  });

  it('never draws a frame older than one already drawn, whatever order decoding finishes in', async () => {
    const decoder = manualDecoder();
    const { hook, sockets, drawing } = setup(decoder.decode);
    const socket = sockets.last();
    act(() => socket.open());
    await nextFrame();
    act(() => {
      socket.frame({ revision: 1, pass: 1 });
      socket.frame({ revision: 1, pass: 2 });
    });
    decoder.pending[1].finish();
    await settle();
    decoder.pending[0].finish();
    await settle();
    expect(drawing.draws).toHaveLength(1);
    expect(hook.result.current.frame).toMatchObject({ revision: 1, pass: 2 });
    expect(decoder.pending.every((p) => p.image.closed)).toBe(true);

    // a late frame of an older revision is not even decoded
    hook.rerender({ scene: moved(1) });
    await nextFrame();
    act(() => socket.frame({ revision: 2, pass: 1 }));
    decoder.pending[2].finish();
    await settle();
    act(() => socket.frame({ revision: 1, pass: 3 }));
    expect(decoder.pending).toHaveLength(3);
    expect(hook.result.current.frame).toMatchObject({ revision: 2, pass: 1 });
  });

  it('drops frames it cannot read or decode and keeps drawing the next ones', async () => {
    const decoder = manualDecoder();
    const { hook, sockets, drawing } = setup(decoder.decode);
    const socket = sockets.last();
    act(() => socket.open());
    await nextFrame();
    act(() => {
      socket.receive(new Uint8Array([0, 0]).buffer);
      socket.receive(new Uint8Array([0, 0, 0, 99, 1]).buffer);
      socket.frame({ revision: 1, pass: 1 });
    });
    decoder.pending[0].fail();
    await settle();
    act(() => socket.frame({ revision: 1, pass: 2 }));
    decoder.pending[1].finish();
    await settle();
    expect(drawing.draws).toHaveLength(1);
    expect(hook.result.current.frame).toMatchObject({ pass: 2 });
  });

  it('shows a refused scene with its field errors until a newer revision renders, and clears them on unmount', async () => {
    const { hook, sockets, onFieldErrors } = setup();
    const socket = sockets.last();
    act(() => socket.open());
    await nextFrame();
    const problem = { title: 'Invalid scene', status: 400, detail: '1 invalid field', errors: [{ field: 'objects[0].radius', message: 'must be greater than 0' }] };
    act(() => socket.receive({ revision: 1, problem }));
    expect(hook.result.current.problem).toMatchObject({ status: 400, title: 'Invalid scene' });
    expect(onFieldErrors).toHaveBeenLastCalledWith({ 'objects[0].radius': 'must be greater than 0' });

    hook.rerender({ scene: moved(1) });
    await nextFrame();
    act(() => socket.frame({ revision: 2, pass: 1 }));
    await settle();
    expect(hook.result.current.problem).toBeNull();
    expect(onFieldErrors).toHaveBeenLastCalledWith({});

    act(() => socket.receive({ revision: 1, problem })); // older than the frame drawn
    expect(hook.result.current.problem).toBeNull();
    hook.rerender({ scene: moved(2) });
    await nextFrame();
    act(() => socket.receive({ revision: 3, problem }));
    expect(onFieldErrors).toHaveBeenLastCalledWith({ 'objects[0].radius': 'must be greater than 0' });
    const calls = onFieldErrors.mock.calls.length;
    hook.unmount();
    expect(onFieldErrors).toHaveBeenCalledTimes(calls + 1);
    expect(onFieldErrors).toHaveBeenLastCalledWith({});
  });

  it('takes a problem that names no revision as the answer to the newest one sent', async () => {
    const { hook, sockets } = setup();
    const socket = sockets.last();
    act(() => socket.open());
    await nextFrame();
    act(() => socket.frame({ revision: 1, pass: 1 }));
    await settle();
    hook.rerender({ scene: moved(1) });
    await nextFrame();
    act(() => socket.receive({ revision: null, problem: { title: 'Service Unavailable', status: 503, detail: 'busy' } }));
    expect(hook.result.current.problem).toMatchObject({ status: 503, detail: 'busy' });
    act(() => socket.drop(1000, 'idle')); // answered in full: no reconnection until the next edit
    expect(hook.result.current.connection.state).toBe('paused');
  });

  it('gives up at once when the server refuses the message itself, until the next edit', async () => {
    const { hook, sockets } = setup();
    act(() => sockets.last().open());
    await nextFrame();
    act(() => sockets.last().drop(1009, 'a message may be at most 1000 bytes'));
    expect(hook.result.current.connection).toEqual({ state: 'failed', reason: 'a message may be at most 1000 bytes' });
    act(() => vi.advanceTimersByTime(60_000));
    expect(sockets.opened).toHaveLength(1);
    hook.rerender({ scene: moved(1) });
    expect(sockets.opened).toHaveLength(2);
  });

  it('reconnects a dropped connection with growing delays and sends the current scene again', async () => {
    const { hook, sockets } = setup();
    act(() => sockets.last().open());
    await nextFrame();
    act(() => sockets.last().frame({ revision: 1, pass: 1 }));
    act(() => sockets.last().drop());
    expect(hook.result.current.connection).toEqual({ state: 'retrying', reason: 'the connection was refused or lost', delayMillis: RETRY_DELAYS[0] });

    act(() => vi.advanceTimersByTime(RETRY_DELAYS[0] - 20));
    hook.rerender({ scene: moved(2) }); // edited while disconnected
    await nextFrame(); // at most 16 ms
    expect(sockets.opened).toHaveLength(1);
    act(() => vi.advanceTimersByTime(20));
    expect(sockets.opened).toHaveLength(2);
    act(() => sockets.last().drop()); // refused
    expect(hook.result.current.connection).toMatchObject({ state: 'retrying', delayMillis: RETRY_DELAYS[1] });
    act(() => vi.advanceTimersByTime(RETRY_DELAYS[1]));
    act(() => sockets.last().open());
    await nextFrame();
    expect(sockets.last().messages()).toEqual([{ revision: 2, scene: moved(2), width: 64, height: 48 }]);
  });

  it('gives up after the last retry; an edit or Reconnect tries again', async () => {
    const { hook, sockets } = setup();
    act(() => sockets.last().drop(1013, 'too many sessions'));
    for (const delay of RETRY_DELAYS) {
      act(() => vi.advanceTimersByTime(delay));
      act(() => sockets.last().drop(1013, 'too many sessions'));
    }
    expect(sockets.opened).toHaveLength(RETRY_DELAYS.length + 1);
    expect(hook.result.current.connection).toEqual({ state: 'failed', reason: 'too many sessions' });
    act(() => vi.advanceTimersByTime(60_000));
    expect(sockets.opened).toHaveLength(RETRY_DELAYS.length + 1);

    act(() => hook.result.current.reconnect());
    expect(sockets.opened).toHaveLength(RETRY_DELAYS.length + 2);
    act(() => sockets.last().drop());
    expect(hook.result.current.connection.state).toBe('retrying');
  });

  it('lets an idle session go once its picture is final, and reconnects on the next edit', async () => {
    const { hook, sockets } = setup();
    act(() => sockets.last().open());
    await nextFrame();
    act(() => sockets.last().frame({ revision: 1, pass: 5, final: true, format: 'png' }));
    await settle();
    act(() => sockets.last().drop(1000, 'idle'));
    expect(hook.result.current.connection).toEqual({ state: 'paused', reason: 'idle' });
    act(() => vi.advanceTimersByTime(60_000));
    hook.rerender({ scene: structuredClone(SCENE) }); // the same scene again is no edit
    expect(sockets.opened).toHaveLength(1);

    hook.rerender({ scene: moved(1) });
    expect(sockets.opened).toHaveLength(2);
    act(() => sockets.last().open());
    await nextFrame();
    expect(sockets.last().messages()).toEqual([{ revision: 2, scene: moved(1), width: 64, height: 48 }]);
  });
});
