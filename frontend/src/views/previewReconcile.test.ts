import { describe, expect, it } from 'vitest';
import { parseObj } from '../model/obj';
import type { AreaLightDescriptor, LightDescriptor, MeshDescriptor } from '../model/toThree';
import { TETRAHEDRON_OBJ } from '../test/meshes';
import { castsShadow, lightBuild, MAX_SHADOW_LIGHTS, meshBuild, plan, planLights, planMeshes, type MeshBuild } from './previewReconcile';

const mesh = (id: string, index: number, geometry: MeshDescriptor['geometry'] = 'sphere', parsed?: MeshDescriptor['mesh']): MeshDescriptor => ({
  id,
  index,
  geometry,
  mesh: parsed,
  position: [index, 0, 0],
  scale: [1, 1, 1],
  rotation: [0, 0, 0],
  quaternion: [0, 0, 0, 1],
  material: { kind: 'lambert', color: '#808080', diffuse: 0.9 },
  selected: false,
});

const light = (id: string, index: number): LightDescriptor => ({ kind: 'point', radius: 0, id, index, position: [0, 5, 0], color: '#ffffff', intensity: 1, decay: 0, selected: false });
const area = (id: string, index: number, twoSided = false): AreaLightDescriptor => ({
  ...light(id, index), kind: 'area', width: 1, height: 1, lookAt: [0, 0, 0], luminance: 1, twoSided,
});

/** What is shown after applying `next` as the plan says (keys to builds), as the preview keeps it. */
const shownAfter = (next: MeshDescriptor[]) => new Map(planMeshes(new Map(), next).steps.map((s) => [s.key, { build: meshBuild(s.next) }]));

const actions = (p: { steps: { key: string; action: string }[] }) => p.steps.map((s) => [s.key, s.action]);

describe('planMeshes', () => {
  const scene = [mesh('object-1', 0, 'plane'), mesh('object-2', 1), mesh('object-3', 2, 'box')];

  it('creates everything at first', () => {
    const p = planMeshes(new Map(), scene);
    expect(actions(p)).toEqual([['object-1', 'create'], ['object-2', 'create'], ['object-3', 'create']]);
    expect(p.remove).toEqual([]);
  });

  it('updates every entry in place on a drag step: nothing created, nothing removed', () => {
    const moved = scene.map((m) => (m.id === 'object-2' ? { ...m, position: [9, 9, 9] as MeshDescriptor['position'] } : m));
    const p = planMeshes(shownAfter(scene), moved);
    expect(actions(p)).toEqual([['object-1', 'update'], ['object-2', 'update'], ['object-3', 'update']]);
    expect(p.steps[1].next.position).toEqual([9, 9, 9]);
    expect(p.remove).toEqual([]);
  });

  it('removes only what is gone, and hands the others their new indices (deletion, reorder)', () => {
    const deleted = [{ ...scene[0] }, { ...scene[2], index: 1 }];
    const p = planMeshes(shownAfter(scene), deleted);
    expect(p.remove).toEqual(['object-2']);
    expect(p.steps.map((s) => [s.key, s.action, s.next.index])).toEqual([['object-1', 'update', 0], ['object-3', 'update', 1]]);
    const reordered = [{ ...scene[2], index: 0 }, { ...scene[0], index: 1 }, { ...scene[1], index: 2 }];
    const q = planMeshes(shownAfter(scene), reordered);
    expect(q.remove).toEqual([]);
    expect(q.steps.map((s) => [s.key, s.action, s.next.index])).toEqual([['object-3', 'update', 0], ['object-1', 'update', 1], ['object-2', 'update', 2]]);
  });

  it('creates only what is new', () => {
    const p = planMeshes(shownAfter(scene), [...scene, mesh('object-7', 3)]);
    expect(actions(p).at(-1)).toEqual(['object-7', 'create']);
    expect(p.steps.filter((s) => s.action === 'create')).toHaveLength(1);
  });

  it('replaces an entry whose geometry kind or triangles change: removed, then created under its key', () => {
    const a = parseObj(TETRAHEDRON_OBJ);
    const b = parseObj(TETRAHEDRON_OBJ); // the same text parsed again: other triangles for the preview
    const before = [mesh('object-1', 0, 'mesh', a), mesh('object-2', 1, 'sphere')];
    const same = planMeshes(shownAfter(before), [mesh('object-1', 0, 'mesh', a), mesh('object-2', 1, 'sphere')]);
    expect(same.remove).toEqual([]);
    const p = planMeshes(shownAfter(before), [mesh('object-1', 0, 'mesh', b), mesh('object-2', 1, 'box')]);
    expect(p.remove).toEqual(['object-1', 'object-2']);
    expect(actions(p)).toEqual([['object-1', 'create'], ['object-2', 'create']]);
  });

  it('keeps one entry per descriptor when an id comes twice', () => {
    const twice = [mesh('object-1', 0), mesh('object-1', 1)];
    const p = planMeshes(new Map(), twice);
    expect(p.steps.map((s) => s.key)).toEqual(['object-1', 'object-1#2']);
    expect(planMeshes(shownAfter(twice), [mesh('object-1', 0)]).remove).toEqual(['object-1#2']);
  });
});

describe('planLights', () => {
  it('replaces a light that starts or stops casting a shadow, and only that one', () => {
    const five = Array.from({ length: MAX_SHADOW_LIGHTS + 1 }, (_, i) => light(`light-${i + 1}`, i));
    expect(five.map(castsShadow)).toEqual([true, true, true, true, false]);
    const shown = new Map(five.map((l) => [l.id, { build: lightBuild(l) }]));
    // the first light deleted: the last one moves up among those that cast shadows
    const p = planLights(shown, five.slice(1).map((l, i) => ({ ...l, index: i })));
    expect(p.remove).toEqual(['light-5', 'light-1']);
    expect(actions(p)).toEqual([['light-2', 'update'], ['light-3', 'update'], ['light-4', 'update'], ['light-5', 'create']]);
  });

  it('replaces a light whose kind changes or an area light that becomes two-sided, keeps one that only moves', () => {
    const shown = new Map([light('light-1', 0), area('light-2', 1)].map((l) => [l.id, { build: lightBuild(l) }]));
    expect(actions(planLights(shown, [{ ...light('light-1', 0), position: [1, 1, 1] }, { ...area('light-2', 1), width: 3 }]))).toEqual([['light-1', 'update'], ['light-2', 'update']]);
    expect(actions(planLights(shown, [area('light-1', 0), area('light-2', 1, true)]))).toEqual([['light-1', 'create'], ['light-2', 'create']]);
    expect([lightBuild(area('a', 0, true)), lightBuild(area('a', 9)), lightBuild(light('a', 0))]).toEqual(['area2+shadow', 'area', 'point+shadow']);
  });
});

describe('plan', () => {
  it('compares builds by identity', () => {
    const shown = new Map<string, { build: MeshBuild }>([['a', { build: 'sphere' }]]);
    expect(plan(shown, ['a'], (x) => x, (): MeshBuild => 'sphere').steps[0].action).toBe('update');
    expect(plan(shown, ['a'], (x) => x, (): MeshBuild => 'box').steps[0].action).toBe('create');
  });
});
