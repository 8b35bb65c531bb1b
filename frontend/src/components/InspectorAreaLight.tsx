import { resolveLight } from '../model/defaults';
import * as edits from '../model/edits';
import type { AreaLight, ResolvedLightOf } from '../model/types';
import { useSceneStore } from '../store/sceneStore';
import { CheckboxField } from './fields/CheckboxField';
import { ColorField } from './fields/ColorField';
import { NumberField } from './fields/NumberField';
import { VectorField } from './fields/VectorField';
import { labelOf } from './labels';

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
  const setPreview = useSceneStore((s) => s.setPreview);
  const cancelPreview = useSceneStore((s) => s.cancelPreview);
  const r = resolveLight(light) as ResolvedLightOf<'area'>;
  const path = `lights[${index}]`;
  return (
    <section className="inspector-section" aria-label={`${labelOf(light, index)} properties`} data-testid="inspector-light">
      <h3>{labelOf(light, index)}</h3>
      <VectorField
        label="Light position"
        path={`${path}.position`}
        value={r.position}
        hint="The centre of the rectangle (metres)"
        onCommit={(v) => setField(index, 'position', v)}
      />
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
        hint="Brightness; a very small area light lights as a point light of the same intensity"
        onCommit={(v) => setField(index, 'intensity', v)}
      />
      <CheckboxField
        label="Falls off with distance (1/d²)"
        path={`${path}.falloff`}
        checked={r.falloff}
        hint="As a point light's: a very small area light lights as a point light with the same setting"
        onCommit={(v) => setField(index, 'falloff', v)}
      />
      <CheckboxField
        label="Two-sided"
        path={`${path}.twoSided`}
        checked={r.twoSided}
        hint="Off: it shines from its front only (towards its aim). On: from both faces."
        onCommit={(v) => setField(index, 'twoSided', v)}
      />
    </section>
  );
}
