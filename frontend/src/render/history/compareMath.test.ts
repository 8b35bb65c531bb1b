import { describe, expect, it } from 'vitest';
import { clampPosition, compareFrame, containRect, dividerX, positionAfterKey, positionAt } from './compareMath';

describe('compareMath', () => {
  it('draws two renders of one size over exactly the same pixels', () => {
    const frame = compareFrame({ width: 800, height: 600 }, { width: 800, height: 600 });
    expect(frame).toEqual({ width: 800, height: 600 });
    expect(containRect({ width: 800, height: 600 }, frame)).toEqual({ x: 0, y: 0, width: 800, height: 600 });
  });

  it('fits renders of different sizes whole and centred in one frame', () => {
    const frame = compareFrame({ width: 800, height: 600 }, { width: 1280, height: 720 });
    expect(frame).toEqual({ width: 1280, height: 720 });
    // 800x600 scaled by 1.2 to 960x720, centred across 1280
    expect(containRect({ width: 800, height: 600 }, frame)).toEqual({ x: 160, y: 0, width: 960, height: 720 });
    // a half-size render of the same aspect covers the frame as the full one does
    expect(containRect({ width: 640, height: 360 }, frame)).toEqual({ x: 0, y: 0, width: 1280, height: 720 });
  });

  it('maps a pointer to a position, clamped to the frame', () => {
    expect(positionAt(300, 100, 400)).toBe(50);
    expect(positionAt(0, 100, 400)).toBe(0);
    expect(positionAt(900, 100, 400)).toBe(100);
    expect(positionAt(133.3333, 100, 100)).toBe(33.3);
    expect(positionAt(5, 0, 0)).toBe(50);
  });

  it('moves with the keys of a slider', () => {
    expect(positionAfterKey(50, 'ArrowLeft')).toBe(49);
    expect(positionAfterKey(50, 'ArrowRight', true)).toBe(60);
    expect(positionAfterKey(50, 'PageDown')).toBe(40);
    expect(positionAfterKey(95, 'PageUp')).toBe(100);
    expect(positionAfterKey(0.5, 'ArrowDown')).toBe(0);
    expect(positionAfterKey(50, 'Home')).toBe(0);
    expect(positionAfterKey(50, 'End')).toBe(100);
    expect(positionAfterKey(50, 'a')).toBeNull();
  });

  it('puts the divider at the position across the frame', () => {
    expect(dividerX(25, { width: 800, height: 600 })).toBe(200);
    expect(clampPosition(Number.NaN)).toBe(50);
  });
});
