import { memo } from 'react';
import { resolveObject } from '../model/defaults';
import type { MeshState } from '../model/meshCache';
import { boxFootprint, planeToSvg, worldToSvg, type ViewKind, type ViewTransform } from '../model/projection';
import type { SceneObject } from '../model/types';
import { labelOf, MATERIAL_LABELS, meshName } from '../components/labels';
import { MeshGlyph } from './MeshGlyph';
import { PlaneGlyph } from './PlaneGlyph';

const LOADING: MeshState = { status: 'loading' };

/** Props of {@link ObjectGlyph}. */
export interface ObjectGlyphProps {
  kind: ViewKind;
  t: ViewTransform;
  object: SceneObject;
  index: number;
  selected: boolean;
  /** Id of the SVG hatch pattern used for planes seen face-on. */
  hatchId: string;
  /** For a mesh: what is known of its triangles (loading when not given). */
  meshState?: MeshState;
}

/**
 * One object as seen in a plan view: a sphere as a circle, a box as the outline of its rotated
 * footprint (with a tick on its own +x face), a plane edge-on or as a hatched hint, a mesh as its
 * labelled bounding rectangle (see {@link MeshGlyph}). The group
 * carries `data-testid="object-N"`, `data-kind`, `data-selected` and `data-target` (for dragging).
 * Memoised: a drag step changes one object of the scene (the others keep their values, and the
 * view its transform), so only the glyphs whose props changed render again.
 */
export const ObjectGlyph = memo(function ObjectGlyph({ kind, t, object, index, selected, hatchId, meshState = LOADING }: ObjectGlyphProps) {
  const r = resolveObject(object);
  const name = r.type === 'mesh' || r.type === 'gltf' ? meshName(labelOf(object, index), meshState, r.type === 'gltf' ? 'glTF' : 'OBJ') : labelOf(object, index);
  const common = {
    'data-testid': `object-${index}`,
    'data-kind': r.type,
    'data-selected': selected,
    'data-target': `object:${index}`,
    className: `glyph glyph--${r.type}${selected ? ' is-selected' : ''}`,
    role: 'button',
    tabIndex: 0,
    'aria-label': name,
    'aria-pressed': selected,
  } as const;
  const title = <title>{`${name} (${MATERIAL_LABELS[r.material.type]}) — drag to move`}</title>;
  const fill = r.material.color;
  if (r.type === 'plane') {
    return (
      <g {...common}>
        {title}
        <PlaneGlyph kind={kind} t={t} point={r.point} normal={r.normal} color={fill} hatchId={hatchId} />
      </g>
    );
  }
  if (r.type === 'mesh' || r.type === 'gltf') {
    return (
      <g {...common}>
        {title}
        <MeshGlyph kind={kind} t={t} mesh={r} state={meshState} label={labelOf(object, index)} color={fill} />
      </g>
    );
  }
  const [cx, cy] = worldToSvg(kind, t, r.center);
  if (r.type === 'sphere') {
    return (
      <g {...common}>
        {title}
        <circle cx={cx} cy={cy} r={Math.max(3, r.radius * t.zoom)} fill={fill} className="glyph-body" />
        <circle cx={cx} cy={cy} r={2} className="glyph-centre" />
      </g>
    );
  }
  const hull = boxFootprint(kind, r.center, r.size, r.rotation).map((q) => planeToSvg(kind, t, q));
  return (
    <g {...common}>
      {title}
      <polygon points={hull.map((p) => p.join(',')).join(' ')} fill={fill} className="glyph-body" />
      <circle cx={cx} cy={cy} r={2} className="glyph-centre" />
    </g>
  );
});
