import { resolveLight, sceneLights } from '../model/defaults';
import type { ResolvedLightOf } from '../model/types';
import * as edits from '../model/edits';
import { selectDisplayScene, useSceneStore } from '../store/sceneStore';
import { CheckboxField } from './fields/CheckboxField';
import { InspectorAreaLight } from './InspectorAreaLight';
import { ColorField } from './fields/ColorField';
import { NumberField } from './fields/NumberField';
import { NameField } from './fields/NameField';
import { VectorField } from './fields/VectorField';
import { labelOf } from './labels';

/** Props of {@link InspectorLight}. */
export interface InspectorLightProps {
  /** Index of the light in `scene.lights`. */
  index: number;
}

/** Fields of one light: a point light's here, an area light's in {@link InspectorAreaLight}. */
export function InspectorLight({ index }: InspectorLightProps) {
  const lights = useSceneStore((s) => selectDisplayScene(s).lights);
  const light = sceneLights({ lights, objects: [] })[index];
  const setField = useSceneStore((s) => s.setLightField);
  const setPreview = useSceneStore((s) => s.setPreview);
  const cancelPreview = useSceneStore((s) => s.cancelPreview);
  if (!light) return null;
  if (light.type === 'area') return <InspectorAreaLight index={index} light={light} />;
  const r = resolveLight(light) as ResolvedLightOf<'point'>;
  const path = `lights[${index}]`;
  return (
    <section className="inspector-section" aria-label={`${labelOf(light, index)} properties`} data-testid="inspector-light">
      <h3>{labelOf(light, index)}</h3>
      <NameField path={`${path}.name`} value={light.name} onCommit={(name) => setField(index, 'name', name)} />
      <VectorField
        label="Light position"
        path={`${path}.position`}
        value={r.position}
        hint="Where the point light is (metres)"
        onCommit={(v) => setField(index, 'position', v)}
      />
      <NumberField
        label="Radius"
        path={`${path}.radius`}
        value={r.radius}
        min={0}
        step={0.05}
        hint="Metres: 0 is a point (hard shadows); above 0 a glowing sphere of that radius (soft shadows, seen in mirrors)"
        onCommit={(v) => setField(index, 'radius', v)}
      />
      <ColorField
        label="Light color"
        path={`${path}.color`}
        value={r.color}
        hint="Colour of the light (sRGB)"
        onCommit={(c) => setField(index, 'color', c)}
        onPreview={(c) => setPreview(edits.setLightField(useSceneStore.getState().scene, index, 'color', c))}
        onPreviewEnd={cancelPreview}
      />
      <NumberField
        label="Intensity"
        path={`${path}.intensity`}
        value={r.intensity}
        min={0}
        step={0.05}
        hint="Brightness; 1 lights a white chalk surface facing it fully"
        onCommit={(v) => setField(index, 'intensity', v)}
      />
      <CheckboxField
        label="Falls off with distance (1/d²)"
        path={`${path}.falloff`}
        checked={r.falloff}
        hint="Off: the same light at any distance (as POV-Ray's default). On: divided by the squared distance."
        onCommit={(v) => setField(index, 'falloff', v)}
      />
    </section>
  );
}
