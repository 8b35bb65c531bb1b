import { describe, expect, it } from 'vitest';
import { inItems, selectFound, selectOne, toggleItem, type SceneItem } from './selection';

const o = (index: number): SceneItem => ({ kind: 'object', index });
const l = (index: number): SceneItem => ({ kind: 'light', index });

describe('multi-selection', () => {
  it('a plain pick selects one thing; the camera never joins a group', () => {
    expect(selectOne(o(2))).toEqual({ primary: o(2), items: [o(2)] });
    expect(selectOne({ kind: 'camera' })).toEqual({ primary: { kind: 'camera' }, items: [] });
    expect(selectOne(null)).toEqual({ primary: null, items: [] });
  });

  it('toggling adds an item as the new primary, and removing one hands the primary to the last left', () => {
    let s = toggleItem([o(0)], o(0), l(1));
    expect(s).toEqual({ primary: l(1), items: [o(0), l(1)] });
    s = toggleItem(s.items, s.primary, o(3));
    expect(s).toEqual({ primary: o(3), items: [o(0), l(1), o(3)] });
    s = toggleItem(s.items, s.primary, o(3));
    expect(s).toEqual({ primary: l(1), items: [o(0), l(1)] });
    s = toggleItem(s.items, s.primary, o(0));
    s = toggleItem(s.items, s.primary, l(1));
    expect(s).toEqual({ primary: null, items: [] });
  });

  it('toggling from the camera starts afresh; toggling the camera picks it alone', () => {
    expect(toggleItem([], { kind: 'camera' }, o(1))).toEqual({ primary: o(1), items: [o(1)] });
    expect(toggleItem([o(0), o(1)], o(1), { kind: 'target' })).toEqual({ primary: { kind: 'target' }, items: [] });
  });

  it('a box adds what it found once each, or replaces the selection', () => {
    expect(selectFound([o(0)], o(0), [o(0), o(2)], true)).toEqual({ primary: o(2), items: [o(0), o(2)] });
    expect(selectFound([o(0)], o(0), [l(0)], false)).toEqual({ primary: l(0), items: [l(0)] });
    expect(selectFound([o(0)], o(0), [], true)).toEqual({ primary: o(0), items: [o(0)] });
    expect(selectFound([o(0)], o(0), [], false)).toEqual({ primary: null, items: [] });
    expect(selectFound([], { kind: 'camera' }, [o(1)], true)).toEqual({ primary: o(1), items: [o(1)] });
  });

  it('knows what is in it', () => {
    expect(inItems([o(1), l(1)], l(1))).toBe(true);
    expect(inItems([o(1)], l(1))).toBe(false);
    expect(inItems([o(1)], null)).toBe(false);
  });
});
