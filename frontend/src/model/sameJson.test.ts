import { describe, expect, it } from 'vitest';
import { sameJson } from './sameJson';

describe('sameJson', () => {
  it('is true exactly when the JSON texts would be equal, whatever the key order', () => {
    const cases: [unknown, unknown][] = [
      [{ a: 1, b: [1, 2, { c: 'x' }] }, { b: [1, 2, { c: 'x' }], a: 1 }],
      [{ a: 1, b: undefined }, { a: 1 }],
      [{ a: [1, 2] }, { a: [1, 2, 3] }],
      [{ a: { b: 1 } }, { a: { b: 2 } }],
      [{ a: [] }, { a: {} }],
      [{ a: null }, { a: undefined }],
      ['x', 'x'],
      [1, '1'],
    ];
    for (const [a, b] of cases) {
      const json = (v: unknown) => JSON.stringify(v, (_k, x) => (x && typeof x === 'object' && !Array.isArray(x) ? Object.fromEntries(Object.entries(x).sort()) : x));
      expect(sameJson(a, b), JSON.stringify([a, b])).toBe(json(a) === json(b));
    }
  });
});
