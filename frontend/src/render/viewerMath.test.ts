import { describe, expect, it } from 'vitest';
import { actualPixels, fitImage, imagePointAt, MAX_SCALE, panBy, zoomAbout } from './viewerMath';

describe('the full-size viewer’s view', () => {
  it('fits a large image whole and centred, and never enlarges a small one past 1:1', () => {
    expect(fitImage(1000, 600, 2000, 1500)).toEqual({ scale: 0.4, x: 100, y: 0 });
    expect(fitImage(1000, 600, 100, 50)).toEqual({ scale: 1, x: 450, y: 275 });
    expect(fitImage(1000, 600, 100, 50, 2).scale).toBe(0.5);
  });

  it('keeps the image point under the cursor while zooming', () => {
    const v = { scale: 0.4, x: 100, y: 0 };
    const before = imagePointAt(v, 321, 123);
    const zoomed = zoomAbout(v, 3.7, 321, 123);
    const after = imagePointAt(zoomed, 321, 123);
    expect(after[0]).toBeCloseTo(before[0], 9);
    expect(after[1]).toBeCloseTo(before[1], 9);
    expect(zoomAbout(v, 1e9, 0, 0).scale).toBe(MAX_SCALE);
  });

  it('goes to one image pixel per device pixel, and pans', () => {
    expect(actualPixels({ scale: 0.4, x: 100, y: 0 }, 500, 300).scale).toBe(1);
    expect(actualPixels({ scale: 0.4, x: 100, y: 0 }, 500, 300, 2).scale).toBe(0.5);
    expect(panBy({ scale: 2, x: 1, y: 2 }, 10, -5)).toEqual({ scale: 2, x: 11, y: -3 });
  });
});
