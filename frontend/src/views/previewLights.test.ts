import { BackSide, BufferGeometry, DoubleSide, Material, Mesh, Object3D, RectAreaLight, SpotLight, Texture, UniformsLib, Vector3, type MeshBasicMaterial } from 'three';
import { describe, expect, it, vi } from 'vitest';
import { areaLightFrame } from '../model/areaLight';
import * as edits from '../model/edits';
import { carryIds } from '../model/identity';
import { sceneToThree } from '../model/toThree';
import type { Scene, Vec3 } from '../model/types';
import { PreviewContent } from './previewContent';

const SCENE: Scene = {
  objects: [{ type: 'plane' }],
  lights: [
    { type: 'point', position: [2, 5, 2], radius: 0.5, color: '#ff0000' },
    { type: 'area', position: [0, 3, 1], size: [2, 0.5], lookAt: [0, 0, 0], color: '#00ff00', intensity: 2, falloff: true },
  ],
};

function preview(scene: Scene) {
  const content = new PreviewContent();
  let shown = carryIds(null, scene);
  const show = (next: Scene, selection: Parameters<typeof sceneToThree>[1] = null) => {
    shown = carryIds(shown, next);
    content.update(sceneToThree(shown, selection), false);
    return shown;
  };
  show(shown);
  return { content, show, scene: () => shown };
}

const rects = (c: PreviewContent) => c.root.children.filter((o): o is RectAreaLight => o instanceof RectAreaLight);
const spots = (c: PreviewContent) => c.root.children.filter((o): o is SpotLight => o instanceof SpotLight);
/** What a click on light `index` can pick, in order. */
const picks = (c: PreviewContent, index: number) => c.pickables.filter((p) => p.userData.target?.kind === 'light' && p.userData.target.index === index) as Mesh[];
const axis = (o: Object3D, x: number, y: number, z: number) => new Vector3(x, y, z).applyQuaternion(o.quaternion).toArray() as Vec3;
const expectClose = (a: Vec3, b: Vec3) => a.forEach((v, i) => expect(v).toBeCloseTo(b[i], 9));

function created(action: () => void) {
  const next = () => [new Object3D().id, new BufferGeometry().id, new Material().id, new Texture().id];
  const before = next();
  action();
  return next().map((id, i) => id - before[i] - 1);
}

describe('the preview’s sphere and area lights', () => {
  it('draws an area light as a RectAreaLight where the render has it, aimed as areaLightFrame says, with its glowing face', () => {
    const { content } = preview(SCENE);
    expect(UniformsLib).toHaveProperty('LTC_FLOAT_1'); // RectAreaLightUniformsLib.init() ran
    const [rect] = rects(content);
    expect(rect.position.toArray()).toEqual([0, 3, 1]);
    expect([rect.width, rect.height]).toEqual([2, 0.5]);
    expect(rect.color.getHexString()).toBe('00ff00');
    const frame = areaLightFrame([0, 3, 1], [0, 0, 0]);
    expectClose(axis(rect, 1, 0, 0), frame.right);
    expectClose(axis(rect, 0, 0, -1), frame.front);
    expect(rect.intensity).toBeCloseTo((2 * Math.PI) / 1, 9);
    const [spot] = spots(content);
    expect(spot.target.position.toArray()).toEqual([0, 0, 0]);
    expect(spot.angle).toBeCloseTo(Math.PI / 2);
    expect(spot.decay).toBe(2);
    const [marker, glow] = picks(content, 1);
    expect(marker.position.toArray()).toEqual([0, 3, 1]);
    expect(glow.scale.toArray()).toEqual([2, 0.5, 1]);
    expect(glow.quaternion.toArray()).toEqual(rect.quaternion.toArray());
    expect((glow.material as MeshBasicMaterial).side).toBe(BackSide); // it shines from three's -z face
    expect(content.helpers).toContain(marker);
    expect(content.helpers).not.toContain(glow); // mirrors see the light, as in the render
  });

  it('shows a sphere light’s radius as a glowing sphere, and none at radius 0', () => {
    const p = preview(SCENE);
    const [, glow] = picks(p.content, 0);
    expect(glow.visible).toBe(true);
    expect(glow.scale.toArray()).toEqual([0.5, 0.5, 0.5]);
    expect(glow.position.toArray()).toEqual([2, 5, 2]);
    p.show(edits.setLightField(p.scene(), 0, 'radius', 0));
    expect(picks(p.content, 0)).toHaveLength(1); // the marker alone
  });

  it('moves and turns an area light in place; two-sided rebuilds it with a face each way; deleting frees it', () => {
    const p = preview(SCENE);
    const [rect] = rects(p.content);
    expect(created(() => p.show(edits.aimLight(edits.moveLight(p.scene(), 1, [1, 3, 1]), 1, [1, 0, 3])))).toEqual([0, 0, 0, 0]);
    expect(rects(p.content)).toEqual([rect]);
    expectClose(axis(rect, 0, 0, -1), areaLightFrame([1, 3, 1], [1, 0, 3]).front);
    p.show(edits.setLightField(p.scene(), 1, 'twoSided', true));
    const [front, back] = rects(p.content);
    expect(front).not.toBe(rect);
    expectClose(axis(back, 0, 0, -1), axis(front, 0, 0, 1));
    expect((picks(p.content, 1)[1].material as MeshBasicMaterial).side).toBe(DoubleSide);
    const freed = [vi.spyOn(front, 'dispose'), vi.spyOn(back, 'dispose')];
    p.show(edits.removeLight(p.scene(), 1));
    expect(rects(p.content)).toEqual([]);
    expect(spots(p.content)).toEqual([]);
    freed.forEach((f) => expect(f).toHaveBeenCalled());
  });
});
