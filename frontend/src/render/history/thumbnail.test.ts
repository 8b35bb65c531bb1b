import { describe, expect, it } from 'vitest';
import { makeThumbnail, thumbnailSize } from './thumbnail';

describe('thumbnail', () => {
  it('shrinks a render to fit 240 x 160, keeping its aspect', () => {
    expect(thumbnailSize(1920, 1080)).toEqual({ width: 240, height: 135 });
    expect(thumbnailSize(800, 600)).toEqual({ width: 213, height: 160 });
    expect(thumbnailSize(10_000, 1)).toEqual({ width: 240, height: 1 });
  });

  it('makes none of a render that small already, or where the browser cannot decode images', async () => {
    expect(thumbnailSize(200, 100)).toBeNull();
    await expect(makeThumbnail(new Blob(['png']), 200, 100)).resolves.toBeNull();
    // happy-dom has no createImageBitmap
    await expect(makeThumbnail(new Blob(['png']), 1920, 1080)).resolves.toBeNull();
  });
});
