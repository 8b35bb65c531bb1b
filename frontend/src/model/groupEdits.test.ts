import { describe, expect, it } from 'vitest';
import { duplicateItems, nudgeItems, removeItems } from './groupEdits';
import type { Scene } from './types';

const SCENE: Scene = {
  camera: { position: [0, 2, 8], lookAt: [0, 0, 0] },
  lights: [
    { type: 'point', position: [2, 5, -1] },
    { type: 'point', position: [-2, 5, 1] },
  ],
  objects: [
    { type: 'sphere', center: [1, 1, 2], radius: 0.5 },
    { type: 'box', center: [-2, 0.5, 0], size: [1, 1, 1] },
    { type: 'plane', point: [0, 0, 0], normal: [0, 1, 0] },
    { type: 'mesh', obj: 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n', position: [0, 0, -3] },
  ],
};

describe('edits of a multi-selection', () => {
  it('moves objects of every kind and lights by the same offset, leaving the rest', () => {
    const next = nudgeItems(SCENE, [{ kind: 'object', index: 0 }, { kind: 'object', index: 3 }, { kind: 'light', index: 1 }, { kind: 'object', index: 2 }], [1, 0, -1]);
    expect(next.objects[0]).toMatchObject({ center: [2, 1, 1] });
    expect(next.objects[1]).toEqual(SCENE.objects[1]);
    expect(next.objects[2]).toMatchObject({ point: [1, 0, -1] });
    expect(next.objects[3]).toMatchObject({ position: [1, 0, -4] });
    expect(next.lights).toEqual([SCENE.lights![0], { type: 'point', position: [-1, 5, 0] }]);
    expect(SCENE.objects[0]).toMatchObject({ center: [1, 1, 2] }); // the input is unchanged
  });

  it('removes objects and lights together whatever the order they were picked in', () => {
    const next = removeItems(SCENE, [{ kind: 'object', index: 3 }, { kind: 'light', index: 0 }, { kind: 'object', index: 0 }]);
    expect(next.objects).toEqual([SCENE.objects[1], SCENE.objects[2]]);
    expect(next.lights).toEqual([SCENE.lights![1]]);
    expect(removeItems(SCENE, [{ kind: 'object', index: 1 }]).lights).toBe(SCENE.lights);
  });

  it('removing the default light leaves a scene without lights, as removing one light does', () => {
    const next = removeItems({ ...SCENE, lights: undefined }, [{ kind: 'light', index: 0 }, { kind: 'object', index: 0 }]);
    expect(next.lights).toEqual([]);
    expect(next.objects).toHaveLength(3);
  });

  it('duplicates every item aside, after the others, and names the copies', () => {
    const { scene, copies } = duplicateItems(SCENE, [{ kind: 'light', index: 0 }, { kind: 'object', index: 1 }, { kind: 'object', index: 2 }]);
    expect(scene.objects).toHaveLength(6);
    expect(scene.objects.slice(0, 4)).toEqual(SCENE.objects);
    expect(scene.objects[4]).toMatchObject({ type: 'box', center: [-1.5, 0.5, 0.5] });
    expect(scene.objects[5]).toMatchObject({ type: 'plane', point: [0, 0.5, 0] });
    expect(scene.lights).toHaveLength(3);
    expect(scene.lights![2]).toEqual({ type: 'point', position: [2.5, 5, -0.5] });
    expect(copies).toEqual([{ kind: 'object', index: 4 }, { kind: 'object', index: 5 }, { kind: 'light', index: 2 }]);
  });
});
