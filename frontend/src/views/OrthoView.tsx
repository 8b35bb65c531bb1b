import { useMemo, useRef } from 'react';
import { imageAspect, resolveLight, resolveObject, resolveScene, sceneLights } from '../model/defaults';
import { objectAnchor, viewDepth, type ViewKind, type ViewTransform } from '../model/projection';
import { inItems } from '../model/selection';
import { selectDisplayScene, useSceneStore } from '../store/sceneStore';
import { useElementSize } from '../hooks/useElementSize';
import { useMeshLookup } from '../hooks/useMeshes';
import { labelOf } from '../components/labels';
import { AreaLightGlyph } from './AreaLightGlyph';
import { CameraGlyph } from './CameraGlyph';
import { LightGlyph } from './LightGlyph';
import { ObjectGlyph } from './ObjectGlyph';
import { useFitView } from './useFitView';
import { useViewPointer } from './useViewPointer';
import { ViewGrid } from './ViewGrid';

/** Props of {@link OrthoView}. */
export interface OrthoViewProps {
  kind: ViewKind;
  /** Heading shown above the view, e.g. "Top view". */
  title: string;
  /** What the axes are, shown as a subtitle and tooltip. */
  axesHint: string;
}

/**
 * A plan view of the scene (SVG, `data-testid="top-view"` or `"side-view"`): grid, objects,
 * lights, camera with its view cone and target. Click selects (Shift/Ctrl-click adds or takes
 * out), drag moves (the whole selection when several are selected), drag on empty space (or
 * middle button) pans and Shift-drag there selects in a box, wheel zooms about the cursor.
 */
export function OrthoView({ kind, title, axesHint }: OrthoViewProps) {
  const box = useRef<HTMLDivElement>(null);
  const svg = useRef<SVGSVGElement>(null);
  const size = useElementSize(box);
  const scene = useSceneStore(selectDisplayScene);
  const selection = useSceneStore((s) => s.selection);
  const selectedItems = useSceneStore((s) => s.selectedItems);
  const view = useSceneStore((s) => s.views[kind]);
  const gridSize = useSceneStore((s) => s.gridSize);
  const meshes = useMeshLookup();
  // one transform while the view stays, so that the glyphs' memo holds across a drag
  const t: ViewTransform = useMemo(() => ({ ...view, width: size.width, height: size.height }), [view, size.width, size.height]);
  const { handlers, marquee } = useViewPointer(kind, svg, t);

  useFitView(kind, size);

  const objects = useMemo(
    () =>
      scene.objects
        .map((object, index) => ({ object, index, depth: object.type === 'plane' ? -Infinity : viewDepth(kind, objectAnchor(resolveObject(object))) }))
        .sort((a, b) => a.depth - b.depth),
    [scene.objects, kind],
  );
  const camera = resolveScene({ camera: scene.camera, objects: [] }).camera;
  const cameraSelected = selection?.kind === 'camera' || selection?.kind === 'target' ? selection.kind : null;
  return (
    <section className="ortho-view" aria-label={title}>
      <header className="panel-header">
        <h2 title={axesHint}>{title}</h2>
        <span className="panel-header__hint">{axesHint}</span>
        <button type="button" className="small" title="Zoom both views to show the whole scene" onClick={() => useSceneStore.getState().requestFit()}>
          Fit
        </button>
      </header>
      <div className="ortho-view__canvas" ref={box}>
        <svg
          ref={svg}
          data-testid={`${kind}-view`}
          role="group"
          aria-label={`${title}: click to select, Shift-click to add, drag to move, wheel to zoom, drag empty space to pan, Shift-drag it to select in a box`}
          width={t.width}
          height={t.height}
          viewBox={`0 0 ${t.width} ${t.height}`}
          {...handlers}
        >
          <defs>
            <pattern id={`plane-hatch-${kind}`} width="10" height="10" patternUnits="userSpaceOnUse" patternTransform="rotate(45)">
              <line x1="0" y1="0" x2="0" y2="10" stroke="currentColor" strokeWidth="1.5" />
            </pattern>
          </defs>
          <ViewGrid kind={kind} t={t} step={gridSize} />
          {objects.map(({ object, index }) => (
            <ObjectGlyph
              key={index}
              kind={kind}
              t={t}
              object={object}
              index={index}
              selected={(selection?.kind === 'object' && selection.index === index) || inItems(selectedItems, { kind: 'object', index })}
              hatchId={`plane-hatch-${kind}`}
              meshState={object.type === 'mesh' || object.type === 'gltf' ? meshes(object) : undefined}
            />
          ))}
          <CameraGlyph kind={kind} t={t} camera={camera} aspect={imageAspect(scene)} selected={cameraSelected} />
          {sceneLights(scene).map((light, index) => {
            const r = resolveLight(light);
            const selected = (selection?.kind === 'light' && selection.index === index) || inItems(selectedItems, { kind: 'light', index });
            if (r.type === 'area') {
              const aimed = selection?.kind === 'lightAim' && selection.index === index;
              return <AreaLightGlyph key={index} kind={kind} t={t} index={index} light={r} label={labelOf(light, index)} selected={selected ? 'light' : aimed ? 'aim' : null} />;
            }
            return <LightGlyph key={index} kind={kind} t={t} index={index} position={r.position} color={r.color} intensity={r.intensity} radius={r.radius} selected={selected} />;
          })}
          {marquee && <rect className="marquee" data-testid="marquee" x={marquee.x} y={marquee.y} width={marquee.width} height={marquee.height} />}
        </svg>
      </div>
    </section>
  );
}
