import { describe, expect, it } from 'vitest';
import { addAreaLight, addLight, addModel, addObject, duplicateLight, duplicateObject } from './edits';
import { duplicateItems } from './groupEdits';
import { uniqueName } from './naming';
import type { Scene } from './types';

describe('names of new things', () => {
  it('numbers a kind on from the things already there, skipping the numbers objects and lights already carry', () => {
    const scene: Scene = { objects: [{ type: 'sphere', name: 'Sphere 1' }], lights: [{ type: 'point', name: 'Sphere 2' }] };
    expect(uniqueName(scene, 'Sphere')).toBe('Sphere 3');
    expect(uniqueName(scene, 'Box')).toBe('Box 1');
    expect(uniqueName(scene, 'Box', true, 4)).toBe('Box 5');
  });

  it('keeps a file name as it is while free, then numbers it from 2', () => {
    const scene: Scene = { objects: [{ type: 'mesh', name: 'teapot', asset: 'sha256-' + '0'.repeat(64) }] };
    expect(uniqueName(scene, 'duck', false)).toBe('duck');
    expect(uniqueName(scene, 'teapot', false)).toBe('teapot 2');
  });

  it('gives every object and light the editor adds a non-empty name no other has', () => {
    let scene: Scene = { objects: [] };
    for (const kind of ['sphere', 'box', 'sphere', 'plane', 'mesh'] as const) scene = addObject(scene, kind);
    scene = addLight(addAreaLight(addLight(scene)));
    scene = addModel(addModel(scene, { type: 'gltf', name: 'duck', asset: 'sha256-' + '1'.repeat(64) }), { type: 'gltf', name: 'duck', asset: 'sha256-' + '1'.repeat(64) });
    // the default light, written out by the first addLight, is the scene's own
    const names = [...scene.objects, ...scene.lights!.slice(1)].map((item) => ('name' in item ? item.name : undefined));
    expect(names.every((n) => typeof n === 'string' && n.length > 0)).toBe(true);
    expect(new Set(names).size).toBe(names.length);
    expect(scene.objects.map((o) => o.name)).toEqual(['Sphere 1', 'Box 2', 'Sphere 3', 'Plane 4', 'Mesh 5', 'duck', 'duck 2']);
    expect(scene.lights!.map((l) => ('name' in l ? l.name : undefined))).toEqual([undefined, 'Light 2', 'Area light 3', 'Light 4']);
  });
});

describe('names of copies', () => {
  it('number a duplicate apart from everything, a multi-selection’s copies apart from each other too', () => {
    let scene: Scene = { objects: [] };
    scene = addObject(addObject(scene, 'sphere'), 'box');
    scene = { ...scene, objects: [...scene.objects, { type: 'sphere', name: 'ball' }, { type: 'sphere' }] };
    scene = addLight(scene);
    expect(duplicateObject(scene, 0).objects[1].name).toBe('Sphere 5');
    expect(duplicateObject(scene, 2).objects[3].name).toBe('ball 2');
    expect(duplicateObject(scene, 3).objects[4]).not.toHaveProperty('name'); // unnamed stays unnamed
    expect((duplicateLight(scene, 1).lights![2] as { name?: string }).name).toBe('Light 3');
    const { scene: copied } = duplicateItems(scene, [{ kind: 'object', index: 0 }, { kind: 'object', index: 2 }, { kind: 'object', index: 1 }]);
    expect(copied.objects.slice(4).map((o) => o.name)).toEqual(['Sphere 5', 'ball 2', 'Box 7']);
    const names = copied.objects.map((o) => o.name).filter(Boolean);
    expect(new Set(names).size).toBe(names.length);
  });
});
