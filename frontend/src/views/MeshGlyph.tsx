import type { MeshState } from '../model/meshCache';
import { meshBounds } from '../model/obj';
import { boundsToSvgRect, worldToSvg, type ViewKind, type ViewTransform } from '../model/projection';
import type { ResolvedObjectOf } from '../model/types';

/** Side of the square shown while a mesh's triangles are not known (metres; at least 12 px). */
const PLACEHOLDER_SIZE = 0.5;

/** Props of {@link MeshGlyph}. */
export interface MeshGlyphProps {
  kind: ViewKind;
  t: ViewTransform;
  /** The mesh, defaults filled in. */
  mesh: ResolvedObjectOf<'mesh'> | ResolvedObjectOf<'gltf'>;
  /** What is known of its triangles. */
  state: MeshState;
  /** The label written at the rectangle's top-left corner, e.g. "Mesh 3". */
  label: string;
  color: string;
}

/**
 * A mesh in a plan view: the rectangle its world bounding box covers (dashed, lightly filled so a
 * press anywhere inside picks it up), its label, and a dot at its position (what a drag moves).
 * While its triangles load, or when they cannot be read, a small dashed square at its position
 * says so instead.
 */
export function MeshGlyph({ kind, t, mesh, state, label, color }: MeshGlyphProps) {
  const [px, py] = worldToSvg(kind, t, mesh.position);
  let rect: { x: number; y: number; width: number; height: number };
  let text = label;
  if (state.status === 'ready') {
    rect = boundsToSvgRect(kind, t, meshBounds(mesh, state.mesh));
  } else {
    const side = Math.max(12, PLACEHOLDER_SIZE * t.zoom);
    rect = { x: px - side / 2, y: py - side / 2, width: side, height: side };
    text = `${label} (${state.status === 'loading' ? `loading…${state.progress ? ` ${Math.round(100 * state.progress)}%` : ''}` : mesh.type === 'gltf' ? 'glTF error' : 'OBJ error'})`;
  }
  return (
    <>
      <rect {...rect} fill={color} className={`glyph-body mesh-outline${state.status === 'ready' ? '' : ' is-placeholder'}`} />
      <text x={rect.x + 3} y={rect.y - 4} className="glyph-label">
        {text}
      </text>
      <circle cx={px} cy={py} r={2} className="glyph-centre" />
    </>
  );
}
