/** three.js geometries of parsed meshes, one per parsed OBJ, disposed when no longer drawn. */
import type { BufferGeometry } from 'three';
import { FirstDraws } from './firstDraw';
import { meshGeometry } from '../model/meshGeometry';
import type { ParsedObj } from '../model/obj';

/**
 * Keeps one geometry per parsed OBJ (the mesh cache hands out the same parse for as long as a
 * mesh's OBJ is unchanged, so moving or recolouring a mesh reuses its geometry); {@link sweep}
 * disposes those not asked for since the last sweep: a mesh removed, or given another OBJ. A large
 * new geometry starts undrawn and grows part by part ({@link draws}, stepped by the preview's frames).
 */
export class MeshGeometryCache {
  /** The new large geometries not yet drawn whole. */
  readonly draws = new FirstDraws<BufferGeometry>();
  private readonly live = new Map<ParsedObj, BufferGeometry>();
  private used = new Set<ParsedObj>();

  get(parsed: ParsedObj): BufferGeometry {
    this.used.add(parsed);
    let geometry = this.live.get(parsed);
    if (!geometry) {
      geometry = meshGeometry(parsed);
      this.draws.start(geometry, parsed.triangleCount);
      this.live.set(parsed, geometry);
    }
    return geometry;
  }

  /** Disposes every geometry not asked for since the last sweep. */
  sweep(): void {
    for (const [parsed, geometry] of this.live) {
      if (!this.used.has(parsed)) {
        this.draws.forget(geometry);
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
    for (const geometry of this.live.values()) {
      this.draws.forget(geometry);
      geometry.dispose();
    }
    this.live.clear();
  }
}
