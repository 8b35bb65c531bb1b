import { describe, expect, it } from 'vitest';
import { formatMillis, formatRate, formatSeconds, toPercent } from './format';

describe('format', () => {
  it('writes times in ms, s and min', () => {
    expect(formatMillis(850)).toBe('850 ms');
    expect(formatMillis(12_345)).toBe('12.3 s');
    expect(formatMillis(125_000)).toBe('2 min 05 s');
  });

  it('writes rates with a prefix', () => {
    expect(formatRate(4.2e6)).toBe('4.2 M rays/s');
    expect(formatRate(1.5e9)).toBe('1.5 G rays/s');
    expect(formatRate(2500)).toBe('2.5 k rays/s');
    expect(formatRate(12)).toBe('12 rays/s');
  });

  it('rounds progress down to a whole percentage within 0..100', () => {
    expect(toPercent(0.42)).toBe(42);
    expect(toPercent(0.999)).toBe(99);
    expect(toPercent(1)).toBe(100);
    expect(toPercent(-1)).toBe(0);
    expect(toPercent(Number.NaN)).toBe(0);
  });

  it('says seconds in words', () => {
    expect(formatSeconds(1)).toBe('1 second');
    expect(formatSeconds(30)).toBe('30 seconds');
  });
});
