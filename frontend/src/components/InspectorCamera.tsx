import { resolveScene } from '../model/defaults';
import { selectDisplayScene, useSceneStore } from '../store/sceneStore';
import { NumberField } from './fields/NumberField';
import { VectorField } from './fields/VectorField';

/** Props of {@link InspectorCamera}. */
export interface InspectorCameraProps {
  /** Highlights the section (the camera or its target is selected in a view). */
  active?: boolean;
}

/** The render camera: position, target, up and vertical field of view. */
export function InspectorCamera({ active = false }: InspectorCameraProps) {
  const camera = useSceneStore((s) => selectDisplayScene(s).camera);
  const setCamera = useSceneStore((s) => s.setCamera);
  const r = resolveScene({ camera, objects: [] }).camera;
  return (
    <section className={active ? 'inspector-section is-active' : 'inspector-section'} aria-label="Camera properties" data-testid="inspector-camera">
      <h3>Camera</h3>
      <VectorField label="Camera position" path="camera.position" value={r.position} hint="Where the camera is (metres)" onCommit={(v) => setCamera({ position: v })} />
      <VectorField label="Look at" path="camera.lookAt" value={r.lookAt} hint="The point the camera looks at (its target)" onCommit={(v) => setCamera({ lookAt: v })} />
      <VectorField label="Up" path="camera.up" value={r.up} hint="Which way is up in the picture; must not point along the view" onCommit={(v) => setCamera({ up: v })} />
      <NumberField
        label="Field of view (°)"
        path="camera.fov"
        value={r.fov}
        min={0}
        minExclusive
        max={180}
        maxExclusive
        step={1}
        hint="Vertical field of view in degrees, as three.js (smaller zooms in)"
        onCommit={(v) => setCamera({ fov: v })}
      />
    </section>
  );
}
