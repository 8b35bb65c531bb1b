import * as edits from '../model/edits';
import type { Color } from '../model/types';
import { useSceneStore } from '../store/sceneStore';
import { CheckboxField } from './fields/CheckboxField';
import { ColorField } from './fields/ColorField';
import { NumberField } from './fields/NumberField';

/** Props of {@link LightEmissionFields}. */
export interface LightEmissionFieldsProps {
  /** Index of the light in `scene.lights`. */
  index: number;
  /** What the light gives, resolved with its defaults. */
  light: { color: Color; intensity: number; falloff: boolean };
  /** What intensity 1 means for this kind of light. */
  intensityHint: string;
  /** What fall-off does for this kind of light. */
  falloffHint: string;
}

/** The fields every kind of light has for what it gives: its colour, intensity and fall-off. */
export function LightEmissionFields({ index, light, intensityHint, falloffHint }: LightEmissionFieldsProps) {
  const setField = useSceneStore((s) => s.setLightField);
  const setPreview = useSceneStore((s) => s.setPreview);
  const cancelPreview = useSceneStore((s) => s.cancelPreview);
  const path = `lights[${index}]`;
  return (
    <>
      <ColorField
        label="Light color"
        path={`${path}.color`}
        value={light.color}
        hint="Colour of the light (sRGB)"
        onCommit={(c) => setField(index, 'color', c)}
        onPreview={(c) => setPreview(edits.setLightField(useSceneStore.getState().scene, index, 'color', c))}
        onPreviewEnd={cancelPreview}
      />
      <NumberField
        label="Intensity"
        path={`${path}.intensity`}
        value={light.intensity}
        min={0}
        step={0.05}
        hint={intensityHint}
        onCommit={(v) => setField(index, 'intensity', v)}
      />
      <CheckboxField
        label="Falls off with distance (1/d²)"
        path={`${path}.falloff`}
        checked={light.falloff}
        hint={falloffHint}
        onCommit={(v) => setField(index, 'falloff', v)}
      />
    </>
  );
}
