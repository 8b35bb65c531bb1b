import { describe, expect, it } from 'vitest';
import { fitView } from './fitView';

describe('fitView', () => {
  it('letterboxes a wide panel to the camera aspect, centred', () => {
    expect(fitView(1000, 300, 4 / 3, 1)).toEqual({ box: { width: 400, height: 300, left: 300, top: 0 }, pixels: { width: 400, height: 300 } });
  });

  it('letterboxes a tall panel', () => {
    expect(fitView(400, 900, 2, 1)).toEqual({ box: { width: 400, height: 200, left: 0, top: 350 }, pixels: { width: 400, height: 200 } });
  });

  it('asks for device pixels, rounded, keeping the aspect', () => {
    const fit = fitView(641, 481, 4 / 3, 2);
    expect(fit.pixels).toEqual({ width: 1282, height: 962 });
    expect(fit.pixels.width / fit.pixels.height).toBeCloseTo(4 / 3, 2);
  });

  it("asks for no more than the server's default limit, keeping the aspect", () => {
    expect(fitView(1900, 1000, 4 / 3, 2).pixels).toEqual({ width: 2048, height: 1536 });
    expect(fitView(3000, 3000, 1 / 4, 1).pixels).toEqual({ width: 512, height: 2048 });
  });

  it('never asks for less than one pixel, nor trusts an odd aspect or ratio', () => {
    expect(fitView(0, 0, 4 / 3, 1).pixels).toEqual({ width: 1, height: 1 });
    expect(fitView(300, 200, Number.NaN, 0).pixels).toEqual({ width: 200, height: 200 });
  });
});
