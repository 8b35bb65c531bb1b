import { areaLightOutline } from '../model/areaLight';
import { planeToSvg, type ViewKind, type ViewTransform } from '../model/projection';
import type { ResolvedLightOf } from '../model/types';

/** Props of {@link AreaLightGlyph}. */
export interface AreaLightGlyphProps {
  kind: ViewKind;
  t: ViewTransform;
  light: ResolvedLightOf<'area'>;
  index: number;
  /** Its name in the editor (`Area light 2`). */
  label: string;
  /** Which of its two handles is selected (the light or its aim), if either. */
  selected: 'light' | 'aim' | null;
}

/** Length in pixels of the arrow showing the way the light faces, when it faces along the view's plane. */
const ARROW = 26;

/**
 * An area light in a plan view: its rectangle as seen from there (a line edge-on) in its own colour,
 * arrows the way it shines (both ways when two-sided), a dashed sight line to its aim, and two
 * handles: the light (`data-testid="light-N"`, drag to move it; it keeps facing its aim) and the
 * aim (`data-testid="light-aim-N"`, drag to turn it), as the camera and its target. The aim is drawn
 * on top: seen from above, a light facing down has its aim at its centre, and is grabbed by its
 * rectangle.
 */
export function AreaLightGlyph({ kind, t, light, index, label, selected }: AreaLightGlyphProps) {
  const o = areaLightOutline(kind, light.position, light.size, light.lookAt);
  const corners = o.corners.map((c) => planeToSvg(kind, t, c));
  const [cx, cy] = planeToSvg(kind, t, o.centre);
  const [ax, ay] = planeToSvg(kind, t, o.aim);
  const down = kind === 'top' ? 1 : -1;
  const arrow = (sign: number) => {
    const [dx, dy] = [sign * o.front[0] * ARROW, sign * down * o.front[1] * ARROW];
    if (Math.hypot(dx, dy) < 3) return null; // it faces along the view: the rectangle says it
    const len = Math.hypot(dx, dy);
    const [ux, uy] = [dx / len, dy / len];
    const tip = [cx + dx, cy + dy];
    const head = `M ${tip[0] - 6 * ux + 4 * uy} ${tip[1] - 6 * uy - 4 * ux} L ${tip[0]} ${tip[1]} L ${tip[0] - 6 * ux - 4 * uy} ${tip[1] - 6 * uy + 4 * ux}`;
    return <path key={sign} d={`M ${cx} ${cy} L ${tip[0]} ${tip[1]} ${head}`} className="area-light-front" data-testid={`light-front-${index}`} />;
  };
  return (
    <g className={`area-light-glyph${selected ? ' is-active' : ''}`}>
      <line x1={cx} y1={cy} x2={ax} y2={ay} className="camera-sight" aria-hidden="true" />
      <g
        data-testid={`light-${index}`}
        data-target={`light:${index}`}
        data-selected={selected === 'light'}
        className={`glyph glyph--light glyph--area-light${selected === 'light' ? ' is-selected' : ''}`}
        role="button"
        tabIndex={0}
        aria-label={label}
        aria-pressed={selected === 'light'}
      >
        <title>{`${label} (${light.size[0]} x ${light.size[1]} m, ${light.color}, intensity ${light.intensity}${light.twoSided ? ', two-sided' : ''}) — drag to move; it keeps facing its aim`}</title>
        <polygon points={corners.map((c) => c.join(',')).join(' ')} fill={light.color} className="glyph-body area-light-rect" />
        {arrow(1)}
        {light.twoSided && arrow(-1)}
        <circle cx={cx} cy={cy} r={10} className="glyph-hit" />
        <circle cx={cx} cy={cy} r={3.5} className="glyph-centre" />
      </g>
      <g
        data-testid={`light-aim-${index}`}
        data-target={`lightAim:${index}`}
        data-selected={selected === 'aim'}
        className={`glyph glyph--target${selected === 'aim' ? ' is-selected' : ''}`}
        role="button"
        tabIndex={0}
        aria-label={`${label} aim`}
        aria-pressed={selected === 'aim'}
        transform={`translate(${ax} ${ay})`}
      >
        <title>{`${label} aim (look at) — drag to turn the light`}</title>
        <circle r={9} className="glyph-hit" />
        <circle r={5} className="glyph-body target-ring" />
        <path d="M -8 0 H -3 M 3 0 H 8 M 0 -8 V -3 M 0 3 V 8" className="target-cross" />
      </g>
    </g>
  );
}
