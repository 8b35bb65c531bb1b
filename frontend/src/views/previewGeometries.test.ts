import { describe, expect, it, vi } from 'vitest';
import { parseObj } from '../model/obj';
import { TETRAHEDRON_OBJ } from '../test/meshes';
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
});
