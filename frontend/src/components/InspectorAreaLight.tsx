import { resolveLight } from '../model/defaults';
import type { AreaLight, ResolvedLightOf } from '../model/types';
import { useSceneStore } from '../store/sceneStore';
import { CheckboxField } from './fields/CheckboxField';
import { VectorField } from './fields/VectorField';
import { LightEmissionFields } from './LightEmissionFields';
import { LightSection } from './LightSection';

/** Props of {@link InspectorAreaLight}. */
export interface InspectorAreaLightProps {
  /** Index of the light in `scene.lights`. */
  index: number;
  /** The light as the views show it (the preview's while a drag is under way). */
  light: AreaLight;
}

const WH = ['w', 'h'] as const;

/** Fields of one area light: where it is, its width and height, where it faces, its light. */
export function InspectorAreaLight({ index, light }: InspectorAreaLightProps) {
  const setField = useSceneStore((s) => s.setLightField);
  const r = resolveLight(light) as ResolvedLightOf<'area'>;
  const path = `lights[${index}]`;
  return (
    <LightSection index={index} light={light} position={r.position} positionHint="The centre of the rectangle (metres)">
      <VectorField
        label="Size"
        path={`${path}.size`}
        axes={WH}
        value={r.size}
        min={0}
        minExclusive
        hint="Width and height of the rectangle in metres (width level with the ground unless it faces straight up or down)"
        onCommit={(v) => setField(index, 'size', v)}
      />
      <VectorField
        label="Aim (look at)"
        path={`${path}.lookAt`}
        value={r.lookAt}
        hint="The point the light faces; its front shines towards it"
        onCommit={(v) => setField(index, 'lookAt', v)}
      />
      <LightEmissionFields
        index={index}
        light={r}
        intensityHint="Brightness; a very small area light lights as a point light of the same intensity"
        falloffHint="As a point light's: a very small area light lights as a point light with the same setting"
      />
      <CheckboxField
        label="Two-sided"
        path={`${path}.twoSided`}
        checked={r.twoSided}
        hint="Off: it shines from its front only (towards its aim). On: from both faces."
        onCommit={(v) => setField(index, 'twoSided', v)}
      />
    </LightSection>
  );
}
