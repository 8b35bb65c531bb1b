import { describe, expect, it } from 'vitest';
import { presetIndex, resize, SIZE_PRESETS } from './imageSize';

describe('image size', () => {
  it('offers 640x480, 1280x720, 1920x1080 and a square', () => {
    expect(SIZE_PRESETS.map((p) => [p.size.width, p.size.height])).toEqual([[640, 480], [1280, 720], [1920, 1080], [1024, 1024]]);
    expect(presetIndex({ width: 1920, height: 1080 })).toBe(2);
    expect(presetIndex({ width: 800, height: 600 })).toBe(-1);
  });

  it('keeps the aspect ratio when locked, whole pixels within 1..4096; changes one side when not', () => {
    expect(resize({ width: 1280, height: 720 }, 'width', 1920, true)).toEqual({ width: 1920, height: 1080 });
    expect(resize({ width: 800, height: 600 }, 'height', 301, true)).toEqual({ width: 401, height: 301 });
    expect(resize({ width: 1000, height: 10 }, 'width', 10, true)).toEqual({ width: 10, height: 1 });
    expect(resize({ width: 100, height: 1000 }, 'width', 1000, true)).toEqual({ width: 1000, height: 4096 });
    expect(resize({ width: 800, height: 600 }, 'width', 1024, false)).toEqual({ width: 1024, height: 600 });
  });
});
