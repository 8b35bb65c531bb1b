import { describe, expect, it, vi } from 'vitest';
import { recordingContext, tileJson } from '../test/renderFakes';
import { base64ToBytes, paintTile, resetCanvas, type DecodedTile } from './tilePainter';
import type { JobTile } from '../api/jobs';

const TILE = tileJson(32, 64, 0.5) as unknown as JobTile;

function canvasWith(context: CanvasRenderingContext2D) {
  const canvas = document.createElement('canvas');
  vi.spyOn(canvas, 'getContext').mockImplementation(
    () => context as unknown as ReturnType<HTMLCanvasElement['getContext']>,
  );
  return canvas;
}

describe('base64ToBytes', () => {
  it('decodes every byte value', () => {
    const bytes = Uint8Array.from({ length: 256 }, (_, i) => i);
    const base64 = btoa(String.fromCharCode(...bytes));
    expect(base64ToBytes(base64)).toEqual(bytes);
  });
});

describe('paintTile', () => {
  it('draws the decoded tile at its place and size, then frees the bitmap', async () => {
    const recorder = recordingContext();
    const canvas = canvasWith(recorder.context);
    const close = vi.fn();
    const bitmap = { close } as unknown as DecodedTile;
    const decode = vi.fn(async () => bitmap);
    expect(await paintTile(() => canvas, TILE, decode)).toBe(true);
    expect(decode).toHaveBeenCalledWith(TILE.png);
    expect(recorder.draws).toEqual([{ image: bitmap, x: 32, y: 64, width: 32, height: 32 }]);
    expect(close).toHaveBeenCalledTimes(1);
  });

  it('drops a tile that is no longer wanted once decoded', async () => {
    const recorder = recordingContext();
    const close = vi.fn();
    const drawn = await paintTile(
      () => canvasWith(recorder.context),
      TILE,
      async () => ({ close }) as unknown as DecodedTile,
      () => false,
    );
    expect(drawn).toBe(false);
    expect(recorder.draws).toEqual([]);
    expect(close).toHaveBeenCalledTimes(1);
  });

  it('draws nothing without a canvas', async () => {
    const drawn = await paintTile(() => null, TILE, async () => ({}) as DecodedTile);
    expect(drawn).toBe(false);
  });

  it('decodes the PNG bytes through createImageBitmap by default', async () => {
    const received: Blob[] = [];
    vi.stubGlobal('createImageBitmap', async (blob: Blob) => {
      received.push(blob);
      return {};
    });
    try {
      const recorder = recordingContext();
      await paintTile(() => canvasWith(recorder.context), TILE);
      expect(received[0].type).toBe('image/png');
      expect(new Uint8Array(await received[0].arrayBuffer())).toEqual(base64ToBytes(TILE.png));
      expect(recorder.draws).toHaveLength(1);
    } finally {
      vi.unstubAllGlobals();
    }
  });
});

describe('resetCanvas', () => {
  it('sizes the canvas to the image and clears it', () => {
    const recorder = recordingContext();
    const canvas = canvasWith(recorder.context);
    resetCanvas(canvas, 800, 600);
    expect([canvas.width, canvas.height]).toEqual([800, 600]);
    expect(recorder.clears).toBe(1);
  });
});
