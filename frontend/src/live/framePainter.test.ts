import { afterEach, describe, expect, it, vi } from 'vitest';
import { recordingContext } from '../test/renderFakes';
import { encodeFrame, frameHeader } from '../test/liveFakes';
import { decodeImage, drawFrame, type DecodedImage } from './framePainter';
import { decodeFrame } from './protocol';

describe('decodeImage', () => {
  afterEach(() => {
    vi.unstubAllGlobals();
  });

  it("hands createImageBitmap exactly the frame's image bytes, typed by its format", async () => {
    const received: Blob[] = [];
    vi.stubGlobal('createImageBitmap', async (blob: Blob) => {
      received.push(blob);
      return {};
    });
    const frame = decodeFrame(encodeFrame(frameHeader({ format: 'png' }), new Uint8Array([137, 80, 78, 71])));
    await decodeImage(frame.image, frame.mediaType);
    expect(received[0].type).toBe('image/png');
    expect([...new Uint8Array(await received[0].arrayBuffer())]).toEqual([137, 80, 78, 71]);
  });
});

describe('drawFrame', () => {
  it('sizes the canvas to the view and draws the frame over all of it, smoothly upscaled', () => {
    const recorder = recordingContext();
    const canvas = document.createElement('canvas');
    vi.spyOn(canvas, 'getContext').mockReturnValue(recorder.context as never);
    const image = {} as DecodedImage;
    expect(drawFrame(canvas, image, 640, 480)).toBe(true);
    expect([canvas.width, canvas.height]).toEqual([640, 480]);
    expect(recorder.draws).toEqual([{ image, x: 0, y: 0, width: 640, height: 480 }]);
    expect(recorder.context.imageSmoothingEnabled).toBe(true);
    expect(recorder.context.imageSmoothingQuality).toBe('high');
  });

  it('draws nothing on a canvas without a 2D context', () => {
    const canvas = document.createElement('canvas');
    vi.spyOn(canvas, 'getContext').mockReturnValue(null);
    expect(drawFrame(canvas, {} as DecodedImage, 10, 10)).toBe(false);
  });
});
