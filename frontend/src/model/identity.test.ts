import { describe, expect, it } from 'vitest';
import { carryIds, idOf } from './identity';
import * as edits from './edits';
import type { Scene } from './types';

const scene = (): Scene => ({ objects: [{ type: 'box' }, { type: 'sphere' }, { type: 'sphere' }], lights: [{ type: 'point' }] });

describe('carryIds', () => {
  it('numbers a new scene in order, objects together and lights apart', () => {
    const s = carryIds(null, scene());
    expect(s.objects.map(idOf)).toEqual(['object-1', 'object-2', 'object-3']);
    expect(idOf(s.lights![0])).toBe('light-1');
  });

  it('keeps ids through edits: an object edited in place keeps its id, a deletion renumbers nothing', () => {
    const s = carryIds(null, scene());
    const moved = carryIds(s, edits.moveObject(s, 2, [1, 2, 3]));
    expect(moved.objects.map(idOf)).toEqual(['object-1', 'object-2', 'object-3']);
    const deleted = carryIds(moved, edits.removeObject(moved, 0));
    expect(deleted.objects.map(idOf)).toEqual(['object-2', 'object-3']);
    const added = carryIds(deleted, edits.addObject(deleted, 'box'));
    expect(added.objects.map(idOf)).toEqual(['object-2', 'object-3', 'object-4']);
    const duplicated = carryIds(added, edits.duplicateObject(added, 0));
    expect(duplicated.objects.map(idOf)).toEqual(['object-2', 'object-5', 'object-3', 'object-4']);
  });

  it('never shows in JSON', () => {
    const s = carryIds(null, scene());
    expect(JSON.parse(JSON.stringify(s))).toEqual(scene());
  });

  it('numbers area lights among the lights', () => {
    const s = carryIds(null, { objects: [{ type: 'box' }], lights: [{ type: 'point' }, { type: 'area' }] });
    expect(idOf(s.lights![1])).toBe('light-2');
    const added = carryIds(s, edits.addAreaLight(s));
    expect(added.lights!.map(idOf)).toEqual(['light-1', 'light-2', 'light-3']);
    expect(idOf(added.objects[0])).toBe('object-1');
  });
});
