import { act, renderHook } from '@testing-library/react';
import { afterEach, beforeEach, describe, expect, it, vi } from 'vitest';
import { recordingContext } from '../test/renderFakes';
import { fakeSockets, instantDecoder } from '../test/liveFakes';
import type { PatchMessage, RevisionMessage } from './protocol';
import { useLivePreview, type LivePreviewOptions } from './useLivePreview';

const objects = (x: number) => [
  { type: 'sphere', center: [x, 1, 0], radius: 1 },
  { type: 'plane', material: { type: 'chalk', color: '#808080' } },
];
const scene = (x: number) => ({ name: 'patches', objects: objects(x) });

function setup() {
  const sockets = fakeSockets();
  vi.spyOn(HTMLCanvasElement.prototype, 'getContext').mockReturnValue(recordingContext().context as never);
  const onFieldErrors = vi.fn();
  const hook = renderHook((p: Partial<LivePreviewOptions>) => useLivePreview({ scene: scene(0), width: 64, height: 48, onFieldErrors, socketFactory: sockets.factory, decodeImage: instantDecoder, url: 'ws://test/api/preview', ...p }), {
    initialProps: {},
  });
  hook.result.current.canvasRef.current = document.createElement('canvas');
  return { hook, sockets, onFieldErrors };
}

const nextFrame = () => act(async () => void vi.advanceTimersToNextFrame());
const isPatch = (m: RevisionMessage | PatchMessage): m is PatchMessage => 'patch' in m;

describe('the live view sends patches', () => {
  beforeEach(() => {
    vi.useFakeTimers({ toFake: ['setTimeout', 'clearTimeout', 'requestAnimationFrame', 'cancelAnimationFrame'] });
  });
  afterEach(() => {
    vi.useRealTimers();
  });

  it('sends the whole scene first, then each edit as a patch to the revision before it', async () => {
    const { hook, sockets } = setup();
    const socket = sockets.last();
    act(() => socket.open());
    await nextFrame();
    hook.rerender({ scene: scene(1) });
    await nextFrame();
    hook.rerender({ scene: { ...scene(1), name: 'renamed' } });
    await nextFrame();
    const [first, second, third] = socket.messages();
    expect(isPatch(first)).toBe(false);
    expect(second).toEqual({ revision: 2, base: 1, width: 64, height: 48, patch: [{ op: 'replace', path: '/objects/0/center', value: [1, 1, 0] }] });
    expect(third).toMatchObject({ revision: 3, base: 2, patch: [{ op: 'replace', path: '/name', value: 'renamed' }] });
    expect(socket.revisions()[2].scene).toEqual({ ...scene(1), name: 'renamed' });
  });

  it('sends the whole scene at once when the server refuses a patch, without showing the refusal', async () => {
    const { hook, sockets, onFieldErrors } = setup();
    const socket = sockets.last();
    act(() => socket.open());
    await nextFrame();
    hook.rerender({ scene: scene(1) });
    await nextFrame();
    const refusal = { title: 'Invalid scene', status: 400, detail: 'base', errors: [{ field: 'base', message: 'is not the revision this view has last read' }] };
    act(() => socket.receive({ revision: 2, problem: refusal }));
    await nextFrame();
    expect(hook.result.current.problem).toBeNull();
    expect(onFieldErrors).not.toHaveBeenCalled();
    expect(socket.messages()[2]).toEqual({ revision: 3, scene: scene(1), width: 64, height: 48 });

    hook.rerender({ scene: scene(2) });
    await nextFrame();
    expect(socket.messages()[3]).toMatchObject({ revision: 4, base: 3 });
  });

  it('shows a patched scene the server finds invalid, and sends the whole scene after it', async () => {
    const { hook, sockets, onFieldErrors } = setup();
    const socket = sockets.last();
    act(() => socket.open());
    await nextFrame();
    hook.rerender({ scene: { ...scene(0), objects: [{ ...objects(0)[0], radius: -1 }, objects(0)[1]] } });
    await nextFrame();
    const invalid = { title: 'Invalid scene', status: 400, detail: '1 invalid field', errors: [{ field: 'objects[0].radius', message: 'must be greater than 0' }] };
    act(() => socket.receive({ revision: 2, problem: invalid }));
    expect(onFieldErrors).toHaveBeenLastCalledWith({ 'objects[0].radius': 'must be greater than 0' });
    await nextFrame();
    expect(isPatch(socket.messages()[2])).toBe(false);

    act(() => socket.receive({ revision: 3, problem: invalid })); // the whole scene's answer: nothing more to send
    await nextFrame();
    expect(socket.sent).toHaveLength(3);
    hook.rerender({ scene: scene(0) });
    await nextFrame();
    expect(isPatch(socket.messages()[3])).toBe(false); // the server holds no base after a problem
  });

  it('starts every socket with the whole scene', async () => {
    const { hook, sockets } = setup();
    act(() => sockets.last().open());
    await nextFrame();
    act(() => sockets.last().frame({ revision: 1, pass: 5, final: true, format: 'png' }));
    act(() => sockets.last().drop(1000, 'idle'));
    hook.rerender({ scene: scene(3) });
    act(() => sockets.last().open());
    await nextFrame();
    expect(sockets.opened).toHaveLength(2);
    expect(sockets.last().messages()).toEqual([{ revision: 2, scene: scene(3), width: 64, height: 48 }]);
  });
});
