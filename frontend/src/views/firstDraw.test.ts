import { describe, expect, it } from 'vitest';
import { DRAW_WHOLE_BELOW, FIRST_PART, FirstDraws, nextDrawn, PART } from './firstDraw';

/** A geometry that records its draw ranges. */
function target() {
  const ranges: [number, number][] = [];
  return { ranges, setDrawRange: (start: number, count: number) => void ranges.push([start, count]) };
}

describe('nextDrawn', () => {
  it('draws a few triangles first, then a part a step, never past the total', () => {
    expect(nextDrawn(0, 200_978)).toBe(FIRST_PART);
    expect(nextDrawn(FIRST_PART, 200_978)).toBe(FIRST_PART + PART);
    expect(nextDrawn(200_000, 200_978)).toBe(200_978);
    expect(nextDrawn(0, 10)).toBe(10);
  });
});

describe('FirstDraws', () => {
  it('leaves a small mesh drawn whole', () => {
    const draws = new FirstDraws();
    const small = target();
    expect(draws.start(small, DRAW_WHOLE_BELOW)).toBe(false);
    expect(small.ranges).toEqual([]);
    expect(draws.active).toBe(false);
    expect(draws.progress()).toBeNull();
  });

  it('grows a large mesh from nothing to whole, each step one part more of its index, reporting the triangles drawn', () => {
    const draws = new FirstDraws();
    const mesh = target();
    const total = 200_978;
    expect(draws.start(mesh, total)).toBe(true);
    expect(mesh.ranges).toEqual([[0, 0]]);
    expect(draws.progress()).toEqual({ drawn: 0, total });
    const seen: number[] = [];
    const firsts: boolean[] = [];
    while (draws.active) {
      firsts.push(draws.step());
      seen.push(draws.progress()?.drawn ?? total);
    }
    // a step with nothing drawn (shaders set up, buffers uploaded), then its first part, which it says
    expect(firsts).toEqual([false, true, false, false, false, false]);
    expect(seen).toEqual([0, FIRST_PART, FIRST_PART + PART, FIRST_PART + 2 * PART, FIRST_PART + 3 * PART, total]);
    // index entries, three a triangle; the last range is the whole geometry, as three.js draws it by default
    expect(mesh.ranges.slice(1)).toEqual([...seen.slice(1, -1).map((t) => [0, 3 * t]), [0, Infinity]]);
    expect(draws.progress()).toBeNull();
  });

  it('sums the meshes still growing, and stops growing one that is forgotten', () => {
    const draws = new FirstDraws();
    const a = target();
    const b = target();
    draws.start(a, 100_000);
    draws.start(b, 300_000);
    draws.step(); // nothing drawn yet
    expect(draws.progress()).toEqual({ drawn: 0, total: 400_000 });
    draws.step();
    expect(draws.progress()).toEqual({ drawn: 2 * FIRST_PART, total: 400_000 });
    draws.step(); // a is whole now (1,024 + 65,536 + ... reaches 100,000 at its third part)
    draws.step();
    expect(draws.progress()).toEqual({ drawn: FIRST_PART + 2 * PART, total: 300_000 });
    draws.forget(b);
    expect(draws.active).toBe(false);
    const steps = b.ranges.length;
    draws.step();
    expect(b.ranges).toHaveLength(steps);
  });
});
