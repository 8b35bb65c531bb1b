import type { ReactNode } from 'react';
import type { Light, Vec3 } from '../model/types';
import { useSceneStore } from '../store/sceneStore';
import { NameField } from './fields/NameField';
import { VectorField } from './fields/VectorField';
import { labelOf } from './labels';

/** Props of {@link LightSection}. */
export interface LightSectionProps {
  /** Index of the light in `scene.lights`. */
  index: number;
  light: Light;
  /** Its position, resolved with its defaults. */
  position: Vec3;
  /** What the position is of, for this kind of light. */
  positionHint: string;
  /** The kind's own fields, after its name and position. */
  children: ReactNode;
}

/** The inspector's section of one light of any kind: its heading, name and position, then the kind's fields. */
export function LightSection({ index, light, position, positionHint, children }: LightSectionProps) {
  const setField = useSceneStore((s) => s.setLightField);
  const path = `lights[${index}]`;
  return (
    <section className="inspector-section" aria-label={`${labelOf(light, index)} properties`} data-testid="inspector-light">
      <h3>{labelOf(light, index)}</h3>
      <NameField path={`${path}.name`} value={light.name} onCommit={(name) => setField(index, 'name', name)} />
      <VectorField label="Light position" path={`${path}.position`} value={position} hint={positionHint} onCommit={(v) => setField(index, 'position', v)} />
      {children}
    </section>
  );
}
