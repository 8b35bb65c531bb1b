import { describe, expect, it } from 'vitest';
import { finite, isFiniteNumber, isRecord } from './json';

describe('JSON narrowing', () => {
  it('tells objects from null, arrays and scalars', () => {
    expect(isRecord({ a: 1 })).toBe(true);
    expect(isRecord({})).toBe(true);
    for (const v of [null, undefined, [], [1], 'x', 3, true]) expect(isRecord(v)).toBe(false);
  });

  it('takes only finite numbers', () => {
    expect(isFiniteNumber(0)).toBe(true);
    expect(isFiniteNumber(-1.5)).toBe(true);
    for (const v of [NaN, Infinity, -Infinity, '1', null, undefined]) expect(isFiniteNumber(v)).toBe(false);
    expect(finite(2)).toBe(2);
    expect(finite(NaN)).toBeUndefined();
    expect(finite('2')).toBeUndefined();
  });
});
