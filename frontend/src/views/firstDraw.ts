/**
 * How a large mesh comes into the 3D preview: a few triangles in its first frame (its shaders are
 * compiled then, a cost of its own in software WebGL), then a part more each frame until all are
 * drawn, so that no frame holds the page for long; the preview says how far it is meanwhile. Pure
 * (no three.js): it moves each geometry's draw range through a {@link DrawRangeTarget}; the
 * preview's frames step it ({@link PreviewEngine.requestRender}).
 */

/** What the growth changes: three.js's `BufferGeometry.setDrawRange` (a range of index entries). */
export interface DrawRangeTarget {
  setDrawRange(start: number, count: number): void;
}

/** Triangles drawn in a mesh's first frame: few, so that the frame costs its shader compile alone. */
export const FIRST_PART = 1024;
/** Triangles added per frame after the first: a 200,000-triangle mesh is in after four. */
export const PART = 65536;
/** Meshes up to this many triangles are drawn whole at once. */
export const DRAW_WHOLE_BELOW = PART;

/** The triangles drawn after one more step, from `drawn` of `total`. */
export function nextDrawn(drawn: number, total: number): number {
  return Math.min(total, drawn === 0 ? FIRST_PART : drawn + PART);
}

/** How much of the growing meshes is drawn: triangles drawn and in all, or null when nothing grows. */
export interface DrawProgress {
  drawn: number;
  total: number;
}

/** A growing geometry: its triangles drawn and in all, and whether its nothing-drawn frame is past. */
interface Growth extends DrawProgress {
  prepared: boolean;
}

/** The geometries still growing, each with its triangles drawn and in all. */
export class FirstDraws<T extends DrawRangeTarget> {
  private readonly growing = new Map<T, Growth>();

  /**
   * Starts drawing `geometry` (of `triangles` triangles) from nothing, when it is large; a small one
   * is left drawn whole. Returns whether it grows.
   */
  start(geometry: T, triangles: number): boolean {
    if (triangles <= DRAW_WHOLE_BELOW) return false;
    geometry.setDrawRange(0, 0);
    this.growing.set(geometry, { drawn: 0, total: triangles, prepared: false });
    return true;
  }

  /** True while some geometry is not fully drawn. */
  get active(): boolean {
    return this.growing.size > 0;
  }

  /**
   * Draws the next part of every growing geometry (a geometry drawn whole is dropped); returns
   * whether one of them drew its first part. A geometry's first step draws nothing: that frame sets
   * up its shaders and uploads its buffers, the next one compiles them in drawing the first part.
   */
  step(): boolean {
    let first = false;
    for (const [geometry, p] of this.growing) {
      if (!p.prepared) {
        p.prepared = true;
        continue;
      }
      first ||= p.drawn === 0;
      p.drawn = nextDrawn(p.drawn, p.total);
      geometry.setDrawRange(0, p.drawn === p.total ? Infinity : 3 * p.drawn);
      if (p.drawn === p.total) this.growing.delete(geometry);
    }
    return first;
  }

  /** Forgets a geometry (disposed before it was fully drawn). */
  forget(geometry: T): void {
    this.growing.delete(geometry);
  }

  /** The triangles drawn and in all of the growing geometries, or null when none grows. */
  progress(): DrawProgress | null {
    if (this.growing.size === 0) return null;
    let drawn = 0;
    let total = 0;
    for (const p of this.growing.values()) {
      drawn += p.drawn;
      total += p.total;
    }
    return { drawn, total };
  }
}
