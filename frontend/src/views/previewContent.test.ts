import { BoxHelper, BufferGeometry, CameraHelper, Material, Object3D, PerspectiveCamera, PointLight, Texture, Vector3, WebGLCubeRenderTarget, type Mesh, type MeshStandardMaterial } from 'three';
import { describe, expect, it, vi } from 'vitest';
import * as edits from '../model/edits';
import { carryIds } from '../model/identity';
import { MeshCache } from '../model/meshCache';
import type { Selection } from '../model/selection';
import { sceneToThree } from '../model/toThree';
import type { Scene } from '../model/types';
import { gridObj, TETRAHEDRON_OBJ } from '../test/meshes';
import { PreviewContent } from './previewContent';

const cache = new MeshCache();

const BASE: Scene = {
  lights: [{ type: 'point', position: [2, 5, 2] }, { type: 'point', position: [-2, 5, 2] }],
  objects: [
    { type: 'plane', point: [0, 0, 0], normal: [0, 1, 0] },
    { type: 'sphere', center: [0, 1, 0], radius: 1, material: { type: 'mirror' } },
    { type: 'box', center: [2, 0.5, 0], material: { type: 'plastic', color: '#ff0000' } },
    { type: 'mesh', obj: TETRAHEDRON_OBJ, position: [-2, 0, 0] },
  ],
};

/** A preview content showing `scene` as the store hands it over (with ids); `show` shows the next version. */
function preview(scene: Scene, selection: Selection = null, frustum = false) {
  const content = new PreviewContent();
  let shown = carryIds(null, scene);
  const show = (next: Scene, selected: Selection = selection, withFrustum = frustum) => {
    shown = carryIds(shown, next);
    content.update(sceneToThree(shown, selected, (m) => cache.get(m)), withFrustum);
    return shown;
  };
  show(shown);
  const picked = (kind: 'object' | 'light', index: number) =>
    content.pickables.find((p) => p.userData.target.kind === kind && p.userData.target.index === index) as Mesh;
  return { content, show, scene: () => shown, object: (i: number) => picked('object', i), marker: (i: number) => picked('light', i) };
}

/** three numbers every object, geometry, material and texture it makes: how many `action` made. */
function created(action: () => void) {
  const next = () => [new Object3D().id, new BufferGeometry().id, new Material().id, new Texture().id];
  const before = next();
  action();
  const [objects, geometries, materials, textures] = next().map((id, i) => id - before[i] - 1);
  return { objects, geometries, materials, textures };
}

const disposed = (thing: { addEventListener(type: 'dispose', listener: () => void): void }) => {
  const listener = vi.fn();
  thing.addEventListener('dispose', listener);
  return listener;
};

/** Which cube maps (their textures) were freed from now on: a cube map is freed with its render target. */
function freedCubeMaps() {
  const dispose = vi.spyOn(WebGLCubeRenderTarget.prototype, 'dispose');
  return () => dispose.mock.contexts.map((target) => (target as WebGLCubeRenderTarget).texture);
}

const pointLights = (content: PreviewContent) => content.root.children.filter((c): c is PointLight => c instanceof PointLight);

describe('PreviewContent', () => {
  it('moves the very mesh on a drag step and builds nothing: no object, geometry, material or cube map', () => {
    const p = preview(BASE, { kind: 'object', index: 2 }, true);
    const children = [...p.content.root.children];
    const box = p.object(2);
    const [geometry, material] = [box.geometry, box.material];
    const drawn = children.flatMap((c) => [(c as Mesh).geometry, (c as Mesh).material as Material]).filter((x) => x !== undefined);
    const freed = drawn.map(disposed);
    const step = () => p.show(edits.moveObject(p.scene(), 2, [3, 0.5, 1]));
    expect(created(step)).toEqual({ objects: 0, geometries: 0, materials: 0, textures: 0 });
    expect(freed.filter((f) => f.mock.calls.length > 0)).toEqual([]);
    expect(p.object(2)).toBe(box);
    expect(box.position.toArray()).toEqual([3, 0.5, 1]);
    expect([box.geometry, box.material]).toEqual([geometry, material]);
    expect(p.content.root.children).toHaveLength(children.length);
    children.forEach((child, i) => expect(p.content.root.children[i]).toBe(child));
    // the selection's box went along
    const helper = children.find((c) => c instanceof BoxHelper)!;
    helper.geometry.computeBoundingBox();
    expect(helper.geometry.boundingBox!.getCenter(new Vector3()).toArray()).toEqual([3, 0.5, 1]);
  });

  it('removes only what was deleted; the others keep their meshes and are picked by their new index', () => {
    const p = preview(BASE);
    const [plane, mirror, box, tetrahedron] = [0, 1, 2, 3].map(p.object);
    const cubeMaps = freedCubeMaps();
    const cubeMap = (mirror.material as MeshStandardMaterial).envMap;
    p.show(edits.removeObject(p.scene(), 1));
    expect([0, 1, 2].map(p.object)).toEqual([plane, box, tetrahedron]);
    expect(p.content.root.children).not.toContain(mirror);
    expect(cubeMaps()).toEqual([cubeMap]);
    const objects = p.scene().objects;
    p.show({ ...p.scene(), objects: [objects[2], objects[0], objects[1]] });
    expect([0, 1, 2].map(p.object)).toEqual([tetrahedron, plane, box]);
    const second = p.marker(1);
    p.show(edits.removeLight(p.scene(), 0));
    expect(p.marker(0)).toBe(second);
    expect(p.marker(1)).toBeUndefined();
  });

  it('gives a recoloured mesh its new material in place, and frees the old one once nothing wears it', () => {
    const p = preview(BASE);
    const box = p.object(2);
    const old = disposed(box.material as Material);
    p.show(edits.setMaterial(p.scene(), 2, { type: 'chalk', color: '#00ff00' }));
    expect(p.object(2)).toBe(box);
    expect(box.material).toMatchObject({ type: 'MeshLambertMaterial' });
    expect(old).toHaveBeenCalledTimes(1);
  });

  it('replaces a mesh given other triangles, and frees the old geometry', () => {
    const p = preview(BASE);
    const tetrahedron = p.object(3);
    const old = disposed(tetrahedron.geometry);
    p.show(edits.setMeshObj(p.scene(), 3, gridObj(2)));
    expect(p.object(3)).not.toBe(tetrahedron);
    expect(p.content.root.children).not.toContain(tetrahedron);
    expect(p.object(3).geometry).not.toBe(tetrahedron.geometry);
    expect(old).toHaveBeenCalledTimes(1);
  });

  it('keeps a mirror’s cube map while it reflects, and frees it when it stops', () => {
    const p = preview(BASE);
    const mirror = p.object(1);
    const copy = mirror.material as MeshStandardMaterial;
    expect(copy.envMap).toBeTruthy();
    const freed = disposed(copy);
    const cubeMaps = freedCubeMaps();
    p.show(edits.moveObject(p.scene(), 1, [0, 2, 0]));
    expect(mirror.material).toBe(copy);
    expect(cubeMaps()).toEqual([]);
    p.show(edits.setMaterial(p.scene(), 1, { type: 'chalk' }));
    expect(p.object(1)).toBe(mirror);
    expect((mirror.material as MeshStandardMaterial).envMap ?? null).toBeNull();
    expect(freed).toHaveBeenCalledTimes(1);
    expect(cubeMaps()).toEqual([copy.envMap]);
  });

  it('keeps each light through a move; a deleted light takes its shadow map and marker with it; one that starts casting a shadow is rebuilt', () => {
    const five: Scene = { ...BASE, lights: [0, 1, 2, 3, 4].map((i) => ({ type: 'point', position: [i, 5, 0] })) };
    const p = preview(five);
    const lights = pointLights(p.content);
    expect(lights.map((l) => l.castShadow)).toEqual([true, true, true, true, false]);
    expect(created(() => p.show(edits.moveLight(p.scene(), 1, [1, 6, 0])))).toEqual({ objects: 0, geometries: 0, materials: 0, textures: 0 });
    expect(pointLights(p.content)).toEqual(lights);
    expect(lights[1].position.toArray()).toEqual([1, 6, 0]);
    const shadow = vi.spyOn(lights[0].shadow, 'dispose');
    const marker = disposed(p.marker(0).material as Material);
    p.show(edits.removeLight(p.scene(), 0));
    expect(shadow).toHaveBeenCalledTimes(1);
    expect(marker).toHaveBeenCalledTimes(1);
    const now = pointLights(p.content);
    expect(now.slice(0, 3)).toEqual(lights.slice(1, 4));
    expect(now[3]).not.toBe(lights[4]);
    expect(now.map((l) => l.castShadow)).toEqual([true, true, true, true]);
  });

  it('keeps a light’s shadow camera on the scene’s depth range as it changes', () => {
    const p = preview(BASE);
    const [light] = pointLights(p.content);
    const far = light.shadow.camera.far;
    p.show(edits.moveObject(p.scene(), 2, [0, 0.5, -300]));
    const camera = light.shadow.camera;
    expect(camera.far).toBeGreaterThan(2 * far);
    expect(camera.projectionMatrix.elements).toEqual(new PerspectiveCamera(90, 1, camera.near, camera.far).projectionMatrix.elements);
  });

  it('shows the selection’s box and the orbit view’s frustum while asked, kept from update to update', () => {
    const p = preview(BASE, null, true);
    const frustum = p.content.root.children.find((c) => c instanceof CameraHelper)!;
    expect(p.content.helpers).toContain(frustum);
    p.show(p.scene(), { kind: 'object', index: 2 });
    expect(p.content.root.children).toContain(frustum);
    const box = p.content.root.children.find((c) => c instanceof BoxHelper)!;
    expect(p.content.helpers).toContain(box);
    const freed = [disposed(box.geometry), disposed(frustum.geometry)];
    p.show(p.scene(), null, false);
    expect(p.content.root.children.some((c) => c instanceof BoxHelper || c instanceof CameraHelper)).toBe(false);
    expect(p.content.helpers).not.toContain(box);
    freed.forEach((f) => expect(f).toHaveBeenCalledTimes(1));
  });
});
