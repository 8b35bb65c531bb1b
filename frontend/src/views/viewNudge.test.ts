import { beforeEach, describe, expect, it } from 'vitest';
import type { Scene } from '../model/types';
import { useSceneStore } from '../store/sceneStore';
import { nudgeSelection, nudgeStep } from './viewNudge';

const store = () => useSceneStore.getState();

describe('arrow keys in the 3D views', () => {
  beforeEach(() => {
    const scene: Scene = { objects: [{ type: 'sphere', center: [0, 1, 0], radius: 1 }, { type: 'box', center: [3, 0.5, 0] }] };
    store().resetTo(scene, [], []);
  });

  it('move along the world axis nearest where the arrow points on screen', () => {
    // looking down -z (the default camera): right is +x, "up" on the floor is away, -z
    expect(nudgeStep('ArrowRight', false, [0, -0.2, -1], [1, 0, 0], 0.5)).toEqual([0.5, 0, 0]);
    expect(nudgeStep('ArrowLeft', false, [0, -0.2, -1], [1, 0, 0], 0.5)).toEqual([-0.5, 0, 0]);
    expect(nudgeStep('ArrowUp', false, [0, -0.2, -1], [1, 0, 0], 0.5)).toEqual([0, 0, -0.5]);
    expect(nudgeStep('ArrowDown', false, [0, -0.2, -1], [1, 0, 0], 0.5)).toEqual([0, 0, 0.5]);
    // looking along +x from the side: right is +z
    expect(nudgeStep('ArrowRight', false, [1, 0, 0], [0, 0, 1], 1)).toEqual([0, 0, 1]);
    expect(nudgeStep('ArrowUp', false, [1, 0, 0], [0, 0, 1], 1)).toEqual([1, 0, 0]);
    // at 45 degrees the two arrows still take different axes
    const d = Math.SQRT1_2;
    const right = nudgeStep('ArrowRight', false, [d, 0, -d], [d, 0, d], 1)!;
    const up = nudgeStep('ArrowUp', false, [d, 0, -d], [d, 0, d], 1)!;
    expect(right.findIndex((v) => v !== 0)).not.toBe(up.findIndex((v) => v !== 0));
    expect(nudgeStep('ArrowUp', true, [0, 0, -1], [1, 0, 0], 0.25)).toEqual([0, 0.25, 0]);
    expect(nudgeStep('ArrowDown', true, [0, 0, -1], [1, 0, 0], 0.25)).toEqual([0, -0.25, 0]);
    expect(nudgeStep('a', false, [0, 0, -1], [1, 0, 0], 1)).toBeNull();
  });

  it('move the selection, or all of a multi-selection, one undo step a press; nothing without a selection', () => {
    expect(nudgeSelection([0.5, 0, 0])).toBe(false);
    expect(store().past).toHaveLength(0);
    store().select({ kind: 'object', index: 0 });
    expect(nudgeSelection([0.5, 0, 0])).toBe(true);
    expect(store().scene.objects[0]).toMatchObject({ center: [0.5, 1, 0] });
    expect(store().past).toHaveLength(1);
    store().toggleSelect({ kind: 'object', index: 1 });
    expect(nudgeSelection([0, 0, -1])).toBe(true);
    expect(store().scene.objects.map((o) => (o as { center: number[] }).center)).toEqual([
      [0.5, 1, -1],
      [3, 0.5, -1],
    ]);
    expect(store().past).toHaveLength(2);
  });
});
