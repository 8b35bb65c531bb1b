/** three.js geometries of parsed meshes, one per parsed OBJ, disposed when no longer drawn. */
import type { BufferGeometry } from 'three';
import { meshGeometry } from '../model/toThree';
import type { ParsedObj } from '../model/obj';

/**
 * Keeps one geometry per parsed OBJ (the mesh cache hands out the same parse for as long as a
 * mesh's OBJ is unchanged, so moving or recolouring a mesh reuses its geometry); {@link sweep}
 * disposes those not asked for since the last sweep: a mesh removed, or given another OBJ.
 */
export class MeshGeometryCache {
  private readonly live = new Map<ParsedObj, BufferGeometry>();
  private used = new Set<ParsedObj>();

  get(parsed: ParsedObj): BufferGeometry {
    this.used.add(parsed);
    let geometry = this.live.get(parsed);
    if (!geometry) {
      geometry = meshGeometry(parsed);
      this.live.set(parsed, geometry);
    }
    return geometry;
  }

  /** Disposes every geometry not asked for since the last sweep. */
  sweep(): void {
    for (const [parsed, geometry] of this.live) {
      if (!this.used.has(parsed)) {
        geometry.dispose();
        this.live.delete(parsed);
      }
    }
    this.used = new Set();
  }

  /** How many geometries are alive (tests). */
  get size(): number {
    return this.live.size;
  }

  dispose(): void {
    for (const geometry of this.live.values()) geometry.dispose();
    this.live.clear();
  }
}
