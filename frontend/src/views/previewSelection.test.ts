import { describe, expect, it } from 'vitest';
import { NO_MESHES } from '../model/meshCache';
import { STARTER_SCENE } from '../model/starterScene';
import { useSceneStore } from '../store/sceneStore';
import { handleCallbacks, handlesFor, selectionBall } from './previewSelection';

const store = () => useSceneStore.getState();

describe('3D preview selection and handles', () => {
  it('a pick selects; a whole handle drag is one undo step; its values are rounded', () => {
    handleCallbacks.onPick({ kind: 'object', index: 1 }, false);
    expect(store().selection).toEqual({ kind: 'object', index: 1 });
    const start = handlesFor(store().scene, store().selection)!.pose;
    for (let i = 1; i <= 12; i++) handleCallbacks.onPose({ ...start, position: [start.position[0] + i / 30, start.position[1], start.position[2]] });
    expect(store().past).toHaveLength(0);
    expect(store().preview).not.toBeNull();
    handleCallbacks.onRelease();
    expect(store().past).toHaveLength(1);
    const center = (store().scene.objects[1] as { center: number[] }).center;
    expect(center[0]).toBe(Number((start.position[0] + 0.4).toFixed(3)));
    store().undo();
    expect(store().scene).toEqual(STARTER_SCENE);
    handleCallbacks.onPick(null, false);
    expect(store().selection).toBeNull();
  });

  it('a Shift/Ctrl pick adds to the selection or takes out; a Shift click on empty space keeps it', () => {
    handleCallbacks.onPick({ kind: 'object', index: 0 }, false);
    handleCallbacks.onPick({ kind: 'light', index: 0 }, true);
    expect(store().selectedItems).toEqual([{ kind: 'object', index: 0 }, { kind: 'light', index: 0 }]);
    expect(store().selection).toEqual({ kind: 'light', index: 0 });
    handleCallbacks.onPick(null, true);
    expect(store().selectedItems).toHaveLength(2);
    handleCallbacks.onPick({ kind: 'object', index: 0 }, true);
    expect(store().selectedItems).toEqual([{ kind: 'light', index: 0 }]);
    handleCallbacks.onPick(null, false);
    expect(store().selectedItems).toEqual([]);
  });

  it('moves a light with its handles; the camera has none in 3D', () => {
    store().select({ kind: 'light', index: 0 });
    const { pose, modes } = handlesFor(store().scene, store().selection)!;
    expect(modes).toEqual(['translate']);
    handleCallbacks.onPose({ ...pose, position: [1, 2, 3] });
    handleCallbacks.onRelease();
    expect(store().scene.lights?.[0].position).toEqual([1, 2, 3]);
    expect(handlesFor(store().scene, { kind: 'camera' })).toBeNull();
  });

  it('frames the selection, or every object when nothing is selected', () => {
    const sphere = STARTER_SCENE.objects.find((o) => o.type === 'sphere')!;
    const index = STARTER_SCENE.objects.indexOf(sphere);
    expect(selectionBall(STARTER_SCENE, { kind: 'object', index }, NO_MESHES).center).toEqual(sphere.center);
    const all = selectionBall(STARTER_SCENE, null, NO_MESHES);
    expect(all.radius).toBeGreaterThan(1);
  });

  it('moves an area light by its centre and turns it by its aim with the 3D handles, one undo step each', () => {
    store().addAreaLight();
    const index = store().scene.lights!.length - 1;
    const light = store().scene.lights![index];
    const past = store().past.length;
    const moved = handlesFor(store().scene, { kind: 'light', index })!;
    expect(moved.pose.position).toEqual(light.position);
    store().select({ kind: 'light', index });
    handleCallbacks.onPose({ ...moved.pose, position: [1, 4, 1] });
    handleCallbacks.onRelease();
    store().select({ kind: 'lightAim', index });
    const aimed = handlesFor(store().scene, store().selection)!;
    expect(aimed).toEqual({ pose: { position: (light as { lookAt: number[] }).lookAt, rotation: [0, 0, 0], scale: [1, 1, 1] }, modes: ['translate'] });
    handleCallbacks.onPose({ ...aimed.pose, position: [2, 0, 2] });
    handleCallbacks.onRelease();
    expect(store().scene.lights![index]).toMatchObject({ position: [1, 4, 1], lookAt: [2, 0, 2] });
    expect(store().past).toHaveLength(past + 2);
    expect(selectionBall(store().scene, { kind: 'lightAim', index }, NO_MESHES).center).toEqual([2, 0, 2]);
    expect(handlesFor(store().scene, { kind: 'lightAim', index: 0 })).toBeNull(); // a point light has no aim
  });
});
