import { describe, expect, it } from 'vitest';
import { itemsInRect } from './boxSelect';
import { worldToSvg, type ViewTransform } from './projection';
import type { Scene } from './types';

const SCENE: Scene = {
  lights: [{ type: 'point', position: [2, 5, -1] }],
  objects: [
    { type: 'sphere', center: [1, 1, 2], radius: 0.5 },
    { type: 'box', center: [-2, 0.5, 0], size: [1, 1, 1] },
    { type: 'plane', point: [0, 0, 0], normal: [0, 1, 0] },
  ],
};
const T: ViewTransform = { zoom: 40, pan: [0, 0], width: 480, height: 320 };

describe('box select', () => {
  it('finds the objects and lights whose anchor the view draws inside the box, not planes', () => {
    const a = worldToSvg('top', T, [0, 0, -2]);
    const b = worldToSvg('top', T, [3, 0, 3]);
    expect(itemsInRect(SCENE, 'top', T, a, b)).toEqual([{ kind: 'object', index: 0 }, { kind: 'light', index: 0 }]);
    // any two opposite corners
    expect(itemsInRect(SCENE, 'top', T, b, a)).toEqual(itemsInRect(SCENE, 'top', T, a, b));
  });

  it('reads depth out of the side view: only height and x count there', () => {
    const a = worldToSvg('side', T, [-3, 0, 0]);
    const b = worldToSvg('side', T, [0, 2, 0]);
    expect(itemsInRect(SCENE, 'side', T, a, b)).toEqual([{ kind: 'object', index: 1 }]);
  });

  it('an empty box finds nothing', () => {
    expect(itemsInRect(SCENE, 'top', T, [0, 0], [1, 1])).toEqual([]);
  });
});
