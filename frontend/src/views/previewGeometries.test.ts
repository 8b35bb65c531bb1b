import { describe, expect, it, vi } from 'vitest';
import { parseObj } from '../model/obj';
import { TETRAHEDRON_OBJ } from '../test/meshes';
import type { ParsedObj } from '../model/obj';
import { DRAW_WHOLE_BELOW } from './firstDraw';
import { MeshGeometryCache } from './previewGeometries';

describe('MeshGeometryCache', () => {
  it('keeps one geometry per parse and disposes those no longer drawn', () => {
    const geometries = new MeshGeometryCache();
    const a = parseObj(TETRAHEDRON_OBJ);
    const b = parseObj(TETRAHEDRON_OBJ);
    const ga = geometries.get(a);
    expect(geometries.get(a)).toBe(ga);
    const gb = geometries.get(b);
    const disposedA = vi.fn();
    const disposedB = vi.fn();
    ga.addEventListener('dispose', disposedA);
    gb.addEventListener('dispose', disposedB);
    geometries.sweep(); // both were used in this frame
    geometries.get(b); // the next frame draws only b (a's mesh was removed or given another OBJ)
    geometries.sweep();
    expect(disposedA).toHaveBeenCalledTimes(1);
    expect(disposedB).not.toHaveBeenCalled();
    expect(geometries.size).toBe(1);
    geometries.dispose();
    expect(disposedB).toHaveBeenCalledTimes(1);
  });

  it('starts a large mesh undrawn, to be drawn part by part, and a small one whole', () => {
    const geometries = new MeshGeometryCache();
    const triangles = DRAW_WHOLE_BELOW + 1;
    const large: ParsedObj = { positions: new Float32Array(9), indices: new Uint32Array(3 * triangles), triangleCount: triangles };
    const small = geometries.get(parseObj(TETRAHEDRON_OBJ));
    expect(small.drawRange.count).toBe(Infinity);
    expect(geometries.draws.active).toBe(false);
    const g = geometries.get(large);
    expect(g.drawRange.count).toBe(0);
    expect(geometries.draws.progress()).toEqual({ drawn: 0, total: triangles });
    while (geometries.draws.active) geometries.draws.step();
    expect(g.drawRange.count).toBe(Infinity);
  });

  it('stops drawing a large mesh removed before it is whole', () => {
    const geometries = new MeshGeometryCache();
    const triangles = 2 * DRAW_WHOLE_BELOW;
    geometries.get({ positions: new Float32Array(9), indices: new Uint32Array(3 * triangles), triangleCount: triangles });
    geometries.sweep();
    geometries.sweep(); // not asked for again: disposed
    expect(geometries.draws.active).toBe(false);
  });
});
