import { worldToSvg, type ViewKind, type ViewTransform } from '../model/projection';
import type { Vec3 } from '../model/types';

/** Props of {@link LightGlyph}. */
export interface LightGlyphProps {
  kind: ViewKind;
  t: ViewTransform;
  position: Vec3;
  color: string;
  intensity: number;
  /** A sphere light's radius in metres (0: a point), drawn to scale around it. */
  radius?: number;
  index: number;
  selected: boolean;
}

const RAYS = Array.from({ length: 8 }, (_, i) => (i * Math.PI) / 4);

/** A point light as a small sun in its own colour (`data-testid="light-N"`), and its sphere to scale when it has a radius. */
export function LightGlyph({ kind, t, position, color, intensity, radius = 0, index, selected }: LightGlyphProps) {
  const [x, y] = worldToSvg(kind, t, position);
  return (
    <g
      data-testid={`light-${index}`}
      data-target={`light:${index}`}
      data-selected={selected}
      className={`glyph glyph--light${selected ? ' is-selected' : ''}`}
      role="button"
      tabIndex={0}
      aria-label={`Light ${index + 1}`}
      aria-pressed={selected}
      transform={`translate(${x} ${y})`}
    >
      <title>{`Light ${index + 1} (${color}, intensity ${intensity}${radius > 0 ? `, radius ${radius} m` : ''}) — drag to move`}</title>
      {radius > 0 && <circle r={radius * t.zoom} stroke={color} className="light-radius" data-testid={`light-radius-${index}`} />}
      <circle r={13} className="glyph-hit" />
      {RAYS.map((a) => (
        <g key={a}>
          <line x1={Math.cos(a) * 9} y1={Math.sin(a) * 9} x2={Math.cos(a) * 13} y2={Math.sin(a) * 13} className="sun-ray-outline" />
          <line x1={Math.cos(a) * 9} y1={Math.sin(a) * 9} x2={Math.cos(a) * 13} y2={Math.sin(a) * 13} stroke={color} className="sun-ray" />
        </g>
      ))}
      <circle r={6.5} fill={color} className="glyph-body sun-disc" />
    </g>
  );
}
