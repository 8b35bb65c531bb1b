import { describe, expect, it } from 'vitest';
import { addAreaLight, addLight, addModel, addObject } from './edits';
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
