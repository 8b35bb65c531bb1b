import { act, render } from '@testing-library/react';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import * as defaults from '../model/defaults';
import type { Scene } from '../model/types';
import { resetSceneStore, useSceneStore } from '../store/sceneStore';
import { TopView } from './TopView';

// counts each glyph's render by the object it resolves (the glyph resolves its object once a render)
vi.mock('../model/defaults', async (importOriginal) => {
  const actual = await importOriginal<typeof import('../model/defaults')>();
  return { ...actual, resolveObject: vi.fn(actual.resolveObject) };
});

const SCENE: Scene = {
  objects: [
    { type: 'sphere', center: [0, 1, 0], radius: 1 },
    { type: 'sphere', center: [3, 1, 0], radius: 1 },
    { type: 'box', center: [-3, 0.5, 0], size: [1, 1, 1] },
  ],
};

describe('the plan views during a drag', () => {
  beforeEach(() => resetSceneStore(SCENE));

  it('render again only the glyph of the object that moved', () => {
    render(<TopView />);
    const resolve = vi.mocked(defaults.resolveObject);
    const unmoved = useSceneStore.getState().scene.objects[1];
    resolve.mockClear();
    act(() => useSceneStore.getState().moveObject(0, [0.5, 1, 0]));
    const rendersOf = (object: unknown) => resolve.mock.calls.filter(([o]) => o === object).length;
    // once each to sort the objects by depth; once more only for the moved one's glyph
    expect(rendersOf(useSceneStore.getState().scene.objects[0])).toBe(2);
    expect(rendersOf(unmoved)).toBe(1);
  });
});
