import { resolveLight, sceneLights } from '../model/defaults';
import type { ResolvedLightOf } from '../model/types';
import { selectDisplayScene, useSceneStore } from '../store/sceneStore';
import { InspectorAreaLight } from './InspectorAreaLight';
import { NumberField } from './fields/NumberField';
import { LightEmissionFields } from './LightEmissionFields';
import { LightSection } from './LightSection';

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
  if (!light) return null;
  if (light.type === 'area') return <InspectorAreaLight index={index} light={light} />;
  const r = resolveLight(light) as ResolvedLightOf<'point'>;
  const path = `lights[${index}]`;
  return (
    <LightSection index={index} light={light} position={r.position} positionHint="Where the point light is (metres)">
      <NumberField
        label="Radius"
        path={`${path}.radius`}
        value={r.radius}
        min={0}
        step={0.05}
        hint="Metres: 0 is a point (hard shadows); above 0 a glowing sphere of that radius (soft shadows, seen in mirrors)"
        onCommit={(v) => setField(index, 'radius', v)}
      />
      <LightEmissionFields
        index={index}
        light={r}
        intensityHint="Brightness; 1 lights a white chalk surface facing it fully"
        falloffHint="Off: the same light at any distance (as POV-Ray's default). On: divided by the squared distance."
      />
    </LightSection>
  );
}
