import { planeInView, planeToSvg, type Vec2, type ViewKind, type ViewTransform } from '../model/projection';
import type { Vec3 } from '../model/types';

/** Props of {@link PlaneGlyph}. */
export interface PlaneGlyphProps {
  kind: ViewKind;
  t: ViewTransform;
  point: Vec3;
  normal: Vec3;
  color: string;
  /** Id of the SVG hatch pattern for the face-on case. */
  hatchId: string;
}

/**
 * An infinite plane in a plan view. Seen edge-on (its normal lies in the view) it is a line
 * with the solid side (behind the normal) shaded; otherwise it covers the whole view, shown as
 * a faint hatch, with a handle at its point and an arrow along the visible part of its normal.
 */
export function PlaneGlyph({ kind, t, point, normal, color, hatchId }: PlaneGlyphProps) {
  const p = planeInView(kind, point, normal);
  const far = (Math.hypot(t.width, t.height) / t.zoom) * 2 + Math.hypot(p.origin[0] - t.pan[0], p.origin[1] - t.pan[1]);
  const at = (a: number, b: number): Vec2 =>
    planeToSvg(kind, t, [p.origin[0] + a * p.along[0] + b * p.normal[0], p.origin[1] + a * p.along[1] + b * p.normal[1]]);
  const [hx, hy] = planeToSvg(kind, t, p.origin);
  if (p.edgeOn) {
    const [a, b] = [at(-far, 0), at(far, 0)];
    const shade = [a, b, at(far, -far), at(-far, -far)];
    return (
      <>
        <polygon points={shade.map((q) => q.join(',')).join(' ')} fill={color} className="plane-shade" />
        <line x1={a[0]} y1={a[1]} x2={b[0]} y2={b[1]} className="plane-line-hit" />
        <line x1={a[0]} y1={a[1]} x2={b[0]} y2={b[1]} stroke={color} className="glyph-body plane-line" />
        <circle cx={hx} cy={hy} r={4} className="glyph-handle" />
      </>
    );
  }
  const arrow = Math.hypot(...p.normal) > 1e-6 ? at(0, 0.8) : null;
  return (
    <>
      <rect x={0} y={0} width={t.width} height={t.height} fill={`url(#${hatchId})`} className="plane-hatch" style={{ color }} />
      {arrow && <line x1={hx} y1={hy} x2={arrow[0]} y2={arrow[1]} className="plane-normal" />}
      <circle cx={hx} cy={hy} r={6} fill={color} className="glyph-body glyph-handle" />
    </>
  );
}
