import { describe, expect, it } from 'vitest';
import { push, redo, startTimeline, undo } from './history';

describe('history', () => {
  it('undoes and redoes in order, and a push forgets the future', () => {
    let t = startTimeline(1);
    t = push(t, 2);
    t = push(t, 3);
    t = undo(t);
    expect(t).toEqual({ past: [1], present: 2, future: [3] });
    t = undo(undo(t));
    expect(t.present).toBe(1);
    t = redo(t);
    expect(t).toEqual({ past: [1], present: 2, future: [3] });
    t = push(t, 9);
    expect(t).toEqual({ past: [1, 2], present: 9, future: [] });
    expect(redo(t)).toBe(t);
  });

  it('keeps at most the limit of steps', () => {
    let t = startTimeline(0);
    for (let i = 1; i <= 10; i++) t = push(t, i, 3);
    expect(t.past).toEqual([7, 8, 9]);
  });
});
