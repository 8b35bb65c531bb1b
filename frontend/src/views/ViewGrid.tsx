import { gridLines, planeToSvg, VIEW_AXES, type ViewKind, type ViewTransform } from '../model/projection';

/** Props of {@link ViewGrid}. */
export interface ViewGridProps {
  kind: ViewKind;
  t: ViewTransform;
  /** Requested spacing in metres (coarsened when lines would be too dense). */
  step: number;
}

const label = (v: number) => String(Math.round(v * 1000) / 1000);

/** Grid lines, the two axes through the origin, and coordinate labels along the edges. */
export function ViewGrid({ kind, t, step }: ViewGridProps) {
  const { us, vs, step: s } = gridLines(kind, t, step);
  const [uName, vName] = VIEW_AXES[kind].names;
  const origin = planeToSvg(kind, t, [0, 0]);
  const every = Math.max(1, Math.ceil(48 / (s * t.zoom)));
  const major = (x: number) => Math.abs(Math.round(x / s) % (every * 2)) === 0;
  const labelled = (x: number) => Math.abs(Math.round(x / s) % every) === 0;
  return (
    <g className="view-grid" aria-hidden="true">
      {us.map((u) => {
        const x = planeToSvg(kind, t, [u, 0])[0];
        return <line key={`u${u}`} x1={x} x2={x} y1={0} y2={t.height} className={major(u) ? 'grid-line grid-line--major' : 'grid-line'} />;
      })}
      {vs.map((v) => {
        const y = planeToSvg(kind, t, [0, v])[1];
        return <line key={`v${v}`} x1={0} x2={t.width} y1={y} y2={y} className={major(v) ? 'grid-line grid-line--major' : 'grid-line'} />;
      })}
      <line x1={origin[0]} x2={origin[0]} y1={0} y2={t.height} className="axis-line axis-line--v" />
      <line x1={0} x2={t.width} y1={origin[1]} y2={origin[1]} className="axis-line axis-line--u" />
      {us.filter((u) => labelled(u) && planeToSvg(kind, t, [u, 0])[0] > 26).map((u) => (
        <text key={`lu${u}`} x={planeToSvg(kind, t, [u, 0])[0] + 2} y={t.height - 4} className="grid-label">
          {label(u)}
        </text>
      ))}
      {vs.filter((v) => labelled(v) && planeToSvg(kind, t, [0, v])[1] < t.height - 16).map((v) => (
        <text key={`lv${v}`} x={2} y={planeToSvg(kind, t, [0, v])[1] - 2} className="grid-label">
          {label(v)}
        </text>
      ))}
      <text x={t.width - 14} y={origin[1] - 4} className="axis-name">{uName}</text>
      <text x={origin[0] + 4} y={kind === 'top' ? t.height - 16 : 14} className="axis-name">
        {vName}
      </text>
    </g>
  );
}
