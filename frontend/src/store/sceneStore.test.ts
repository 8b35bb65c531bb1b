import { describe, expect, it } from 'vitest';
import { nudgeTarget } from '../model/edits';
import { formatScene } from '../model/formatScene';
import { STARTER_SCENE } from '../model/starterScene';
import { parseScene } from '../model/validate';
import { gridObj, TETRAHEDRON_OBJ } from '../test/meshes';
import type { Scene } from '../model/types';
import { resetSceneStore, useSceneStore, type SceneState } from './sceneStore';

const store = () => useSceneStore.getState();

/** Each named action, with a selection to start from where it needs one. */
const ACTIONS: [string, (s: SceneState) => void, SceneState['selection']?][] = [
  ['loadScene', (s) => s.loadScene({ name: 'x', objects: [] })],
  ['newScene', (s) => s.newScene()],
  ['setScene', (s) => s.setScene({ ...STARTER_SCENE, ambient: 0.3 })],
  ['setName', (s) => s.setName('renamed')],
  ['setBackground', (s) => s.setBackground('#000000')],
  ['setAmbient', (s) => s.setAmbient(0.5)],
  ['setImage', (s) => s.setImage({ width: 320 })],
  ['setRender', (s) => s.setRender({ samples: 4, seed: 3 })],
  ['setCamera', (s) => s.setCamera({ fov: 30 })],
  ['addObject(sphere)', (s) => s.addObject('sphere')],
  ['addObject(box)', (s) => s.addObject('box')],
  ['addObject(plane)', (s) => s.addObject('plane')],
  ['addObject(mesh)', (s) => s.addObject('mesh')],
  ['addMesh', (s) => s.addMesh(TETRAHEDRON_OBJ, 2)],
  ['addLight', (s) => s.addLight()],
  ['addAreaLight', (s) => s.addAreaLight()],
  ['duplicateSelected (object)', (s) => s.duplicateSelected(), { kind: 'object', index: 1 }],
  ['duplicateSelected (light)', (s) => s.duplicateSelected(), { kind: 'light', index: 0 }],
  ['deleteSelected (object)', (s) => s.deleteSelected(), { kind: 'object', index: 2 }],
  ['deleteSelected (light)', (s) => s.deleteSelected(), { kind: 'light', index: 1 }],
  ['moveObject', (s) => s.moveObject(1, [3, 0.5, 3])],
  ['setObjectField', (s) => s.setObjectField(1, 'radius', 2)],
  ['setMaterial', (s) => s.setMaterial(0, { type: 'glass', ior: 1.3 })],
  ['setMaterialType', (s) => s.setMaterialType(0, 'metal')],
  ['moveLight', (s) => s.moveLight(0, [1, 2, 3])],
  ['setLightField', (s) => s.setLightField(0, 'falloff', true)],
  ['setLightField (radius)', (s) => s.setLightField(0, 'radius', 0.5)],
  ['moveTarget (camera)', (s) => s.moveTarget({ kind: 'camera' }, [1, 1, 9])],
  ['moveTarget (target)', (s) => s.moveTarget({ kind: 'target' }, [0, 0, 0])],
];

describe('sceneStore', () => {
  it('starts from the still life with no history', () => {
    expect(store().scene).toEqual(STARTER_SCENE);
    expect(store().past).toEqual([]);
    expect(store().selection).toBeNull();
  });

  it.each(ACTIONS)('%s pushes exactly one history entry; undo restores, redo repeats', (_name, act, selection) => {
    if (selection) store().select(selection);
    const before = structuredClone(store().scene);
    act(store());
    const after = structuredClone(store().scene);
    expect(after).not.toEqual(before);
    expect(store().past).toHaveLength(1);
    expect(store().future).toHaveLength(0);
    store().undo();
    expect(store().scene).toEqual(before);
    expect(store().past).toHaveLength(0);
    store().redo();
    expect(store().scene).toEqual(after);
    expect(store().past).toHaveLength(1);
  });

  it('pushes nothing for an edit that changes nothing', () => {
    store().setName('still-life');
    store().moveObject(99, [0, 0, 0]);
    store().deleteSelected();
    expect(store().past).toHaveLength(0);
  });

  it('never changes the scene it was given', () => {
    const scene: Scene = { name: 'mine', objects: [{ type: 'sphere', center: [0, 0, 0] }] };
    const copy = structuredClone(scene);
    store().loadScene(scene);
    store().moveObject(0, [1, 1, 1]);
    store().setObjectField(0, 'radius', 3);
    expect(scene).toEqual(copy);
  });

  it('makes one drag one history entry, however many steps it had', () => {
    const before = structuredClone(store().scene);
    for (let i = 1; i <= 20; i++) store().dragTo({ kind: 'object', index: 1 }, [i / 10, 0.5, 0]);
    expect(store().past).toHaveLength(0);
    expect(store().scene).toEqual(before);
    expect(store().preview?.objects[1]).toMatchObject({ center: [2, 0.5, 0] });
    store().commitPreview();
    expect(store().preview).toBeNull();
    expect(store().past).toHaveLength(1);
    expect(store().scene.objects[1]).toMatchObject({ center: [2, 0.5, 0] });
    store().undo();
    expect(store().scene).toEqual(before);
  });

  it('adds no entry for a drag that ends where it started or is cancelled', () => {
    const center = (STARTER_SCENE.objects[1] as { center: [number, number, number] }).center;
    store().dragTo({ kind: 'object', index: 1 }, [9, 9, 9]);
    store().dragTo({ kind: 'object', index: 1 }, center);
    store().commitPreview();
    store().dragTo({ kind: 'light', index: 0 }, [9, 9, 9]);
    store().cancelPreview();
    expect(store().past).toHaveLength(0);
    expect(store().preview).toBeNull();
  });

  it('selects what it adds or duplicates, and clears a selection that no longer exists', () => {
    store().addObject('box');
    expect(store().selection).toEqual({ kind: 'object', index: STARTER_SCENE.objects.length });
    store().duplicateSelected();
    expect(store().selection).toEqual({ kind: 'object', index: STARTER_SCENE.objects.length + 1 });
    store().undo();
    store().undo();
    expect(store().selection).toBeNull();
    store().addLight();
    expect(store().selection).toEqual({ kind: 'light', index: 2 });
    store().deleteSelected();
    expect(store().selection).toBeNull();
  });

  it('moves, duplicates and deletes a multi-selection, each as one undo step', () => {
    const start = store().scene;
    store().select({ kind: 'object', index: 0 });
    store().toggleSelect({ kind: 'object', index: 1 });
    store().toggleSelect({ kind: 'light', index: 0 });
    expect(store().selectedItems).toHaveLength(3);
    expect(store().selection).toEqual({ kind: 'light', index: 0 });
    // a drag of the group: many previews, one entry
    for (let i = 1; i <= 6; i++) store().dragItemsBy([i / 6, 0, 0]);
    expect(store().past).toHaveLength(0);
    store().commitPreview();
    expect(store().past).toHaveLength(1);
    const moved = store().scene;
    expect(moved.lights![0].position![0]).toBe(start.lights![0].position![0] + 1);
    expect(moved.objects[2]).toEqual(start.objects[2]);
    store().nudgeSelected([0, 0, -0.5]);
    expect(store().past).toHaveLength(2);
    store().duplicateSelected();
    expect(store().past).toHaveLength(3);
    expect(store().scene.objects).toHaveLength(start.objects.length + 2);
    expect(store().selectedItems).toEqual([
      { kind: 'object', index: start.objects.length },
      { kind: 'object', index: start.objects.length + 1 },
      { kind: 'light', index: start.lights!.length },
    ]);
    store().deleteSelected();
    expect(store().past).toHaveLength(4);
    expect(store().scene.objects).toHaveLength(start.objects.length);
    expect(store().selectedItems).toEqual([]);
    store().undo();
    store().undo();
    store().undo();
    store().undo();
    expect(store().scene).toEqual(start);
  });

  it('keeps only the selected items that still exist after undo', () => {
    store().addObject('box');
    const box = { kind: 'object' as const, index: store().scene.objects.length - 1 };
    store().toggleSelect({ kind: 'object', index: 0 });
    expect(store().selectedItems).toEqual([box, { kind: 'object', index: 0 }]);
    store().undo();
    expect(store().selectedItems).toEqual([{ kind: 'object', index: 0 }]);
  });

  it('selecting one thing, the camera or nothing ends a multi-selection', () => {
    store().select({ kind: 'object', index: 0 });
    store().toggleSelect({ kind: 'object', index: 1 });
    store().select({ kind: 'camera' });
    expect(store().selectedItems).toEqual([]);
    store().toggleSelect({ kind: 'object', index: 1 });
    store().selectBox([{ kind: 'object', index: 0 }], true);
    expect(store().selectedItems).toEqual([{ kind: 'object', index: 1 }, { kind: 'object', index: 0 }]);
    store().select(null);
    expect(store().selectedItems).toEqual([]);
  });

  it('materialises the default light when a scene without lights gets one more', () => {
    store().loadScene({ objects: [] });
    store().addLight();
    expect(store().scene.lights).toHaveLength(2);
    expect(store().scene.lights?.[0]).toMatchObject({ position: [5, 8, 5] });
  });

  it('keeps shared overrides when the material kind changes, the colour only where it means the same', () => {
    store().loadScene({ objects: [{ type: 'sphere', material: { type: 'plastic', color: '#123456', specular: 0.2, diffuse: 0.3 } }] });
    store().setMaterialType(0, 'metal');
    expect(store().scene.objects[0].material).toEqual({ type: 'metal', color: '#123456', specular: 0.2, diffuse: 0.3 });
    // a mirror's or glass's colour is a tint: a blue plastic does not become a blue-tinted glass
    store().setMaterialType(0, 'glass');
    expect(store().scene.objects[0].material).toEqual({ type: 'glass', specular: 0.2 });
    store().setMaterial(0, { type: 'glass', color: '#eeffee' });
    store().setMaterialType(0, 'mirror');
    expect(store().scene.objects[0].material).toEqual({ type: 'mirror', color: '#eeffee' });
  });

  it('saves values without float noise: nudges, drags and typed sums', () => {
    store().loadScene({ objects: [{ type: 'sphere', center: [-0.4, 1, 0] }] });
    store().setPreview(nudgeTarget(store().scene, { kind: 'object', index: 0 }, [-0.2, 0, 0]));
    store().commitPreview();
    expect(store().scene.objects[0]).toMatchObject({ center: [-0.6, 1, 0] });
    store().dragTo({ kind: 'object', index: 0 }, [0.1 + 0.2, 1, 0]);
    expect(store().preview?.objects[0]).toMatchObject({ center: [0.3, 1, 0] });
    store().commitPreview();
    store().setObjectField(0, 'radius', 0.7 + 0.1);
    expect(JSON.stringify(store().scene)).not.toMatch(/\d{13}/);
    expect(store().scene.objects[0]).toMatchObject({ center: [0.3, 1, 0], radius: 0.8 });
  });

  it('keeps view settings out of history', () => {
    store().setView('top', { zoom: 80, pan: [1, 2] });
    store().setSnap(true);
    store().setGridSize(0.25);
    store().select({ kind: 'camera' });
    expect(store().past).toHaveLength(0);
    expect(store()).toMatchObject({ snap: true, gridSize: 0.25, selection: { kind: 'camera' } });
  });

  it('is reset between tests', () => {
    store().setName('dirty');
    resetSceneStore();
    expect(store().scene.name).toBe('still-life');
    expect(store().past).toEqual([]);
  });

  describe('meshes', () => {
    const MESH_SCENE: Scene = {
      name: 'meshes',
      objects: [
        { type: 'sphere' },
        { type: 'mesh', obj: TETRAHEDRON_OBJ, position: [1, 0, 2], scale: 2, rotation: [0, 45, 0], material: { type: 'metal' } },
        { type: 'mesh', file: 'meshes/torus-knot.obj' },
      ],
    };

    it('adds a mesh as one undo step, selected, its OBJ inline, resting on the floor', () => {
      store().addMesh(TETRAHEDRON_OBJ, 2);
      const index = STARTER_SCENE.objects.length;
      expect(store().scene.objects[index]).toMatchObject({ type: 'mesh', obj: TETRAHEDRON_OBJ, scale: 2, rotation: [0, 0, 0] });
      expect((store().scene.objects[index] as { position: number[] }).position[1]).toBe(0); // its lowest corner is its origin
      expect(store().selection).toEqual({ kind: 'object', index });
      expect(store().past).toHaveLength(1);
      store().undo();
      expect(store().scene).toEqual(STARTER_SCENE);
    });

    it('moves a mesh by its position only, a drag being one undo step', () => {
      resetSceneStore(MESH_SCENE);
      store().moveObject(1, [3, 1, -2]);
      expect(store().scene.objects[1]).toEqual({ ...MESH_SCENE.objects[1], position: [3, 1, -2] });
      expect((store().scene.objects[1] as { obj?: string }).obj).toBe(TETRAHEDRON_OBJ);
      for (let i = 1; i <= 10; i++) store().dragTo({ kind: 'object', index: 2 }, [i, 0, 0]);
      store().commitPreview();
      expect(store().scene.objects[2]).toEqual({ type: 'mesh', file: 'meshes/torus-knot.obj', position: [10, 0, 0] });
      expect(store().past).toHaveLength(2);
    });

    it('replaces a file mesh by inline OBJ as one undo step, keeping its placement', () => {
      resetSceneStore(MESH_SCENE);
      store().setMeshObj(2, TETRAHEDRON_OBJ);
      expect(store().scene.objects[2]).toEqual({ type: 'mesh', obj: TETRAHEDRON_OBJ });
      expect(store().past).toHaveLength(1);
      store().undo();
      expect(store().scene.objects[2]).toEqual(MESH_SCENE.objects[2]);
    });

    it('keeps a large inline OBJ unchanged through the JSON text', () => {
      const obj = gridObj(60); // 7 200 triangles, some 150 kB
      const scene: Scene = { ...MESH_SCENE, objects: [...MESH_SCENE.objects, { type: 'mesh', obj, scale: 0.5 }] };
      store().loadScene(scene);
      const parsed = parseScene(formatScene(store().scene));
      expect(parsed.ok && parsed.scene).toEqual(scene);
      if (parsed.ok) store().setScene(parsed.scene);
      expect(store().past).toHaveLength(1); // the same scene again is no new step
      expect((store().scene.objects[3] as { obj: string }).obj).toBe(obj);
    });
  });

  it('forgets the server’s errors of the previous scene on New and on loading a scene, not on an edit', () => {
    const judged = store().scene;
    store().reportServerErrors('render', judged, { 'camera.fov': 'must be greater than 0' });
    store().reportServerErrors('live', judged, { 'render.samples': 'over the budget' });
    store().setAmbient(0.2);
    expect(store().serverErrors.render?.errors).toEqual({ 'camera.fov': 'must be greater than 0' });
    const document = store().documentId;
    store().newScene();
    expect(store().serverErrors).toEqual({ render: null, live: null });
    expect(store().documentId).toBe(document + 1);
    store().reportServerErrors('render', store().scene, { 'camera.fov': 'x' });
    store().loadScene({ objects: [] });
    expect(store().serverErrors.render).toBeNull();
    expect(store().documentId).toBe(document + 2);
  });

  it('adds an area light selected; its aim is a selection only while it is an area light', () => {
    store().addAreaLight();
    const index = store().scene.lights!.length - 1;
    expect(store().selection).toEqual({ kind: 'light', index });
    expect(store().scene.lights![index]).toMatchObject({ type: 'area' });
    store().select({ kind: 'lightAim', index });
    expect(store().selection).toEqual({ kind: 'lightAim', index });
    expect(store().selectedItems).toEqual([]);
    store().moveTarget({ kind: 'lightAim', index }, [1, 0, 1]);
    expect(store().scene.lights![index]).toMatchObject({ lookAt: [1, 0, 1] });
    expect(store().past).toHaveLength(2);
    store().deleteSelected();
    expect(store().scene.lights).toHaveLength(index);
    store().select({ kind: 'lightAim', index: 0 }); // a point light has no aim
    expect(store().selection).toBeNull();
  });
});
