import { describe, expect, it } from 'vitest';
import { selectionForPath } from './ProblemList';

describe('selectionForPath', () => {
  it('finds what a server field path belongs to', () => {
    expect(selectionForPath('objects[12].material.ior')).toEqual({ kind: 'object', index: 12 });
    expect(selectionForPath('lights[0].position[1]')).toEqual({ kind: 'light', index: 0 });
    expect(selectionForPath('camera.lookAt')).toEqual({ kind: 'target' });
    expect(selectionForPath('camera.up')).toEqual({ kind: 'camera' });
    expect(selectionForPath('image.width')).toBeNull();
  });
});
