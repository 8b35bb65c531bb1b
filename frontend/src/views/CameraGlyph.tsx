import { cameraCone, planeToSvg, worldToSvg, type ViewKind, type ViewTransform } from '../model/projection';
import type { Vec3 } from '../model/types';

/** Props of {@link CameraGlyph}. */
export interface CameraGlyphProps {
  kind: ViewKind;
  t: ViewTransform;
  camera: { position: Vec3; lookAt: Vec3; up: Vec3; fov: number };
  /** Image width / height. */
  aspect: number;
  /** Which of the two handles is selected, if any. */
  selected: 'camera' | 'target' | null;
}

/**
 * The render camera: its view cone out to the target's distance, a dashed sight line, the
 * camera body (`data-testid="camera"`) and its target (`data-testid="camera-target"`).
 */
export function CameraGlyph({ kind, t, camera, aspect, selected }: CameraGlyphProps) {
  const cone = cameraCone(kind, camera, aspect).map((q) => planeToSvg(kind, t, q));
  const [cx, cy] = worldToSvg(kind, t, camera.position);
  const [tx, ty] = worldToSvg(kind, t, camera.lookAt);
  const angle = (Math.atan2(ty - cy, tx - cx) * 180) / Math.PI;
  const looksAlong = Math.hypot(tx - cx, ty - cy) < 1;
  const active = selected !== null;
  return (
    <g className={`camera-glyph${active ? ' is-active' : ''}`}>
      {cone.length > 2 && <polygon points={cone.map((p) => p.join(',')).join(' ')} className="camera-cone" aria-hidden="true" />}
      <line x1={cx} y1={cy} x2={tx} y2={ty} className="camera-sight" aria-hidden="true" />
      <g
        data-testid="camera-target"
        data-target="target"
        data-selected={selected === 'target'}
        className={`glyph glyph--target${selected === 'target' ? ' is-selected' : ''}`}
        role="button"
        tabIndex={0}
        aria-label="Camera target"
        aria-pressed={selected === 'target'}
        transform={`translate(${tx} ${ty})`}
      >
        <title>Camera target (look at) — drag to aim the camera</title>
        <circle r={10} className="glyph-hit" />
        <circle r={6} className="glyph-body target-ring" />
        <path d="M -9 0 H -3 M 3 0 H 9 M 0 -9 V -3 M 0 3 V 9" className="target-cross" />
      </g>
      <g
        data-testid="camera"
        data-target="camera"
        data-selected={selected === 'camera'}
        className={`glyph glyph--camera${selected === 'camera' ? ' is-selected' : ''}`}
        role="button"
        tabIndex={0}
        aria-label="Camera"
        aria-pressed={selected === 'camera'}
        transform={`translate(${cx} ${cy}) rotate(${looksAlong ? 0 : angle})`}
      >
        <title>Camera — drag to move it; it keeps looking at its target</title>
        <circle r={12} className="glyph-hit" />
        <rect x={-9} y={-6} width={12} height={12} rx={2} className="glyph-body camera-body" />
        <path d={looksAlong ? 'M -3 -3 L 3 3 M -3 3 L 3 -3' : 'M 3 -3 L 10 -7 L 10 7 L 3 3 Z'} className="glyph-body camera-lens" />
      </g>
    </g>
  );
}
