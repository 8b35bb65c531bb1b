import { describe, expect, it } from 'vitest';
import { applyPatch } from '../test/applyPatch';
import { diffJson, pointerToken } from './scenePatch';

/** A small seeded generator (mulberry32), so a failing case can be run again. */
function random(seed: number): () => number {
  let a = seed >>> 0;
  return () => {
    a = (a + 0x6d2b79f5) >>> 0;
    let t = a;
    t = Math.imul(t ^ (t >>> 15), t | 1);
    t ^= t + Math.imul(t ^ (t >>> 7), t | 61);
    return ((t ^ (t >>> 14)) >>> 0) / 4294967296;
  };
}

type Scene = { objects: Record<string, unknown>[]; [key: string]: unknown };

function sphere(next: () => number): Record<string, unknown> {
  return { type: 'sphere', center: [next(), next(), next()], radius: 0.1 + next(), material: { type: 'chalk', color: '#808080' } };
}

function scene(next: () => number, count: number): Scene {
  return {
    name: 'random',
    camera: { position: [0, 2, 8], lookAt: [0, 1, 0], fov: 50 },
    lights: [{ type: 'point', position: [4, 6, 4] }],
    objects: Array.from({ length: count }, () => sphere(next)),
  };
}

/** One random edit, as the store makes it: a new scene sharing every part it did not touch. */
function edit(before: Scene, next: () => number): Scene {
  const pick = Math.floor(next() * 10);
  const i = Math.floor(next() * before.objects.length);
  const objects = [...before.objects];
  switch (pick) {
    case 0:
      objects[i] = { ...objects[i], center: [next(), next(), next()] };
      return { ...before, objects };
    case 1:
      objects[i] = { ...objects[i], material: { type: 'plastic', color: '#cc3333' } };
      return { ...before, objects };
    case 2:
      objects.splice(i, 0, sphere(next));
      return { ...before, objects };
    case 3:
      if (objects.length > 3) objects.splice(i, 1 + Math.floor(next() * 3), ...(next() < 0.3 ? [sphere(next)] : []));
      return { ...before, objects };
    case 4:
      if (objects.length < 30) objects.push(sphere(next), sphere(next));
      return { ...before, objects };
    case 5:
      return { ...before, camera: { ...(before.camera as object), fov: 20 + 60 * next() } };
    case 6: {
      const rest = { ...before };
      delete rest.name;
      return next() < 0.5 ? rest : { ...before, name: 'n/with~odd keys' };
    }
    case 7: {
      const { radius: _radius, ...without } = objects[i];
      objects[i] = next() < 0.5 ? without : { ...objects[i], 'a/b~c': [1, { d: null }] };
      return { ...before, objects };
    }
    case 8:
      return { ...before, lights: [...(before.lights as unknown[]), { type: 'point', position: [0, 5, 0], intensity: next() }] };
    default:
      objects[i] = { ...objects[i], center: undefined };
      return { ...before, objects, extra: undefined };
  }
}

/** As JSON writes it: `undefined` fields gone. */
const asJson = (value: unknown) => JSON.parse(JSON.stringify(value)) as unknown;

describe('diffJson', () => {
  it('turns the scene before an edit into the scene after, over 600 random edits (applied by an applier of its own)', () => {
    const next = random(45);
    let before = scene(next, 6);
    for (let step = 0; step < 600; step++) {
      const after = edit(before, next);
      const patch = diffJson(before, after);
      expect(asJson(applyPatch(asJson(before), patch)), `step ${step}: ${JSON.stringify(patch)}`).toEqual(asJson(after));
      expect(diffJson(after, asJson(after))).toEqual([]);
      before = after;
    }
  });

  it('touches only the moved object of 10,000, without a look at the others', () => {
    const next = random(7);
    const before = scene(next, 10_000);
    const objects = [...before.objects];
    objects[3] = { ...objects[3], center: [1, 2, 3] };
    expect(diffJson(before, { ...before, objects })).toEqual([{ op: 'replace', path: '/objects/3/center', value: [1, 2, 3] }]);
  });

  it('sees an equal value in a new object as no change, and says what an add, a removal and a new value are', () => {
    const before = { objects: [{ type: 'box', size: [1, 1, 1] }], name: 'a' };
    expect(diffJson(before, { objects: [{ type: 'box', size: [1, 1, 1] }], name: 'a' })).toEqual([]);
    expect(diffJson(before, { ...before, objects: [...before.objects, { type: 'plane' }] })).toEqual([
      { op: 'add', path: '/objects/1', value: { type: 'plane' } },
    ]);
    expect(diffJson(before, { objects: before.objects })).toEqual([{ op: 'remove', path: '/name' }]);
    expect(diffJson(before, { ...before, 'x/y': 1, '~': 2 })).toEqual([
      { op: 'add', path: '/x~1y', value: 1 },
      { op: 'add', path: '/~0', value: 2 },
    ]);
    expect(diffJson(before, { ...before, objects: 3 })).toEqual([{ op: 'replace', path: '/objects', value: 3 }]);
    expect(pointerToken('a~/b')).toBe('a~0~1b');
  });
});
