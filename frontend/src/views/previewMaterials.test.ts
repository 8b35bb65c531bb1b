import { describe, expect, it } from 'vitest';
import { DoubleSide, MeshBasicMaterial, MeshPhongMaterial } from 'three';
import type { MaterialDescriptor } from '../model/toThree';
import { createMaterial, MaterialCache } from './previewMaterials';

const plastic: MaterialDescriptor = { kind: 'phong', color: '#4f8fd6', diffuse: 0.8, specular: 0.5, shininess: 60 };

describe('flat-shaded materials (meshes without normals)', () => {
  it('shades each triangle with its face normal when asked, lit or not', () => {
    for (const d of [plastic, { kind: 'lambert', color: '#ffffff', diffuse: 1 }, { kind: 'standard', color: '#ffffff', metalness: 1, roughness: 0 }] as MaterialDescriptor[]) {
      expect((createMaterial(d, true, null, true) as MeshPhongMaterial).flatShading).toBe(true);
      expect((createMaterial(d, true) as MeshPhongMaterial).flatShading).toBe(false);
    }
    // an unlit colour has no normal to flatten
    expect(createMaterial({ kind: 'basic', color: '#ffffff' }, true, null, true)).toBeInstanceOf(MeshBasicMaterial);
  });

  it('keeps a flat and a smooth copy of one descriptor apart, each shared', () => {
    const cache = new MaterialCache();
    const flat = cache.get(plastic, true, true) as MeshPhongMaterial;
    const smooth = cache.get(plastic, true) as MeshPhongMaterial;
    expect(flat).not.toBe(smooth);
    expect(cache.get(plastic, true, true)).toBe(flat);
    expect([flat.flatShading, smooth.flatShading, flat.side]).toEqual([true, false, DoubleSide]);
    cache.dispose();
  });
});
