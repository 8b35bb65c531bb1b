import { describe, expect, it } from 'vitest';
import { copyText, pasteText } from './clipboard';
import { validateScene } from './validate';
import type { Scene } from './types';

const SCENE: Scene = {
  lights: [{ type: 'point', position: [1, 5, 1] }],
  objects: [
    { type: 'sphere', name: 'ball', center: [1, 1, 0], radius: 1, material: { type: 'glass', ior: 1.3 } },
    { type: 'plane' },
  ],
};

describe('copy and paste as scene JSON', () => {
  it('copies the selection as a scene file of its own', () => {
    const text = copyText(SCENE, { kind: 'object', index: 0 })!;
    const parsed = JSON.parse(text);
    expect(validateScene(parsed).ok).toBe(true);
    expect(parsed.objects).toEqual([SCENE.objects[0]]);
    expect(JSON.parse(copyText(SCENE, { kind: 'light', index: 0 })!)).toMatchObject({ lights: SCENE.lights, objects: [] });
    expect(copyText(SCENE, { kind: 'camera' })).toBeNull();
    expect(copyText(SCENE, null)).toBeNull();
  });

  it('copies a multi-selection as one scene file, and pastes it back all selected', () => {
    const items = [{ kind: 'light' as const, index: 0 }, { kind: 'object' as const, index: 1 }, { kind: 'object' as const, index: 0 }];
    const parsed = JSON.parse(copyText(SCENE, { kind: 'object', index: 0 }, items)!);
    expect(validateScene(parsed).ok).toBe(true);
    expect(parsed.objects).toEqual([SCENE.objects[1], SCENE.objects[0]]);
    expect(parsed.lights).toEqual(SCENE.lights);
    const pasted = pasteText(SCENE, JSON.stringify(parsed))!;
    expect(pasted.items).toEqual([
      { kind: 'object', index: 2 },
      { kind: 'object', index: 3 },
      { kind: 'light', index: 1 },
    ]);
  });

  it('pastes into its own scene beside the original, and into another scene where it was', () => {
    const text = copyText(SCENE, { kind: 'object', index: 0 })!;
    const again = pasteText(SCENE, text)!;
    expect(again.scene.objects).toHaveLength(3);
    expect(again.scene.objects[2]).toEqual({ ...SCENE.objects[0], center: [1.5, 1, 0.5] });
    expect(again.selection).toEqual({ kind: 'object', index: 2 });
    const other = pasteText({ objects: [] }, text)!;
    expect(other.scene.objects).toEqual([SCENE.objects[0]]);
    const light = pasteText(SCENE, copyText(SCENE, { kind: 'light', index: 0 })!)!;
    expect(light.scene.lights).toEqual([SCENE.lights![0], { type: 'point', position: [1.5, 5, 1.5] }]);
    expect(light.selection).toEqual({ kind: 'light', index: 1 });
  });

  it('leaves text that is no scene alone', () => {
    expect(pasteText(SCENE, 'hello')).toBeNull();
    expect(pasteText(SCENE, '{"objects": 3}')).toBeNull();
    expect(pasteText(SCENE, '{"objects": []}')).toBeNull();
  });

  it('copies an area light with its aim selected, and pastes it beside itself facing the same way', () => {
    const scene: Scene = { objects: [], lights: [{ type: 'area', position: [0, 3, 0], lookAt: [0, 0, 0], size: [2, 1] }] };
    const text = copyText(scene, { kind: 'lightAim', index: 0 })!;
    expect(JSON.parse(text).lights).toEqual(scene.lights);
    const pasted = pasteText(scene, text)!;
    expect(pasted.scene.lights![1]).toEqual({ type: 'area', position: [0.5, 3, 0.5], lookAt: [0.5, 0, 0.5], size: [2, 1] });
    expect(pasted.selection).toEqual({ kind: 'light', index: 1 });
  });
});
