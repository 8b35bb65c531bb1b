import { describe, expect, it } from 'vitest';
import { mergeErrors, pathSteps, standingErrors, valueAt } from './standingErrors';
import type { Scene } from './types';

const JUDGED: Scene = {
  camera: { position: [0, 5, 0], lookAt: [0, 0, 0], up: [0, 1, 0] },
  render: { samples: 1024 },
  objects: [{ type: 'sphere', radius: 0.5 }, { type: 'mesh', obj: 'x' }],
};
const ERRORS = {
  'camera.up': 'is parallel',
  'render.samples': 'over the budget',
  'objects[1].obj': 'line 1: unknown',
};

describe('paths', () => {
  it('splits and follows JSON paths', () => {
    expect(pathSteps('objects[2].center[0]')).toEqual(['objects', 2, 'center', 0]);
    expect(valueAt(JUDGED, 'camera.position[1]')).toBe(5);
    expect(valueAt(JUDGED, 'objects[7].radius')).toBeUndefined();
  });
});

describe('standingErrors', () => {
  it('keeps every error while the scene is the one judged', () => {
    expect(standingErrors(ERRORS, JUDGED, structuredClone(JUDGED))).toEqual(ERRORS);
  });

  it('drops an error once its field, or anything its rule reads, changes', () => {
    const moved = { ...JUDGED, camera: { ...JUDGED.camera, position: [0, 5, 1] as [number, number, number] } };
    expect(standingErrors(ERRORS, JUDGED, moved)).toEqual({ 'render.samples': 'over the budget', 'objects[1].obj': 'line 1: unknown' });
    const smaller = { ...JUDGED, image: { width: 100 } };
    expect(standingErrors(ERRORS, JUDGED, smaller)).not.toHaveProperty('render.samples');
    const otherObj = { ...JUDGED, objects: [JUDGED.objects[0], { type: 'mesh' as const, obj: 'y' }] };
    expect(standingErrors(ERRORS, JUDGED, otherObj)).not.toHaveProperty('objects[1].obj');
  });
});

describe('mergeErrors', () => {
  it('puts the editor’s own problems first, one message a field', () => {
    expect(mergeErrors([{ path: 'a', message: 'mine' }, { path: 'a', message: 'second' }], { a: 'server', b: 'server b' })).toEqual({ a: 'mine', b: 'server b' });
  });

  it('lets a server refusal of an area light’s aim go when its position moves, as the camera target’s', () => {
    const judged: Scene = { objects: [], lights: [{ type: 'area', position: [0, 1, 0], lookAt: [0, 1, 0] }] };
    const errors = { 'lights[0].lookAt': 'must differ from lights[0].position' };
    expect(standingErrors(errors, judged, structuredClone(judged))).toEqual(errors);
    expect(standingErrors(errors, judged, { objects: [], lights: [{ type: 'area', position: [0, 2, 0], lookAt: [0, 1, 0] }] })).toEqual({});
  });
});
