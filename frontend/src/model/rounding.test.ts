import { describe, expect, it } from 'vitest';
import { roundChanged, roundNumber } from './rounding';

describe('rounding saved values', () => {
  it('drops float noise and keeps what a person means', () => {
    expect(-0.2 - 0.4).toBe(-0.6000000000000001);
    expect(roundNumber(-0.2 - 0.4)).toBe(-0.6);
    expect(roundNumber(0.1 + 0.2)).toBe(0.3);
    expect(roundNumber(100000.004)).toBe(100000.004);
    expect(roundNumber(1e300)).toBe(1e300);
    expect(roundNumber(-1e-300)).toBe(-1e-300);
    expect(Object.is(roundNumber(-0), 0)).toBe(true);
    expect(roundNumber(Infinity)).toBe(Infinity);
  });

  it('rounds only what an edit wrote, returning the very same objects elsewhere', () => {
    const kept = { center: [1, 2, 0.00045000000000000004], material: { type: 'chalk' } };
    const before = { objects: [kept, { center: [0, 0.00045000000000000004, 0] }], name: 'x' };
    const after = { ...before, objects: [kept, { center: [0.1 + 0.2, 0.00045000000000000004, 0] }] };
    const rounded = roundChanged(before, after);
    expect(rounded).not.toBe(after);
    expect(rounded.objects[0]).toBe(kept);
    expect(rounded.objects[1]).toEqual({ center: [0.3, 0.00045000000000000004, 0] });
    expect(roundChanged(before, before)).toBe(before);
    const added = roundChanged(before, { ...before, objects: [...before.objects, { center: [-0.2 - 0.4, 0, 0] }] });
    expect(added.objects[2]).toEqual({ center: [-0.6, 0, 0] });
    expect(added.objects[1]).toBe(before.objects[1]);
  });
});
