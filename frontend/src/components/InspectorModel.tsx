import { useMeshLookup } from '../hooks/useMeshes';
import type { ResolvedObjectOf, Vec3 } from '../model/types';
import { useSceneStore } from '../store/sceneStore';
import { FieldErrorMessage, useFieldError } from './fieldErrors';
import { NumberField } from './fields/NumberField';
import { VectorField } from './fields/VectorField';

/** Props of {@link InspectorModel}. */
export interface InspectorModelProps {
  /** Index of the model in `scene.objects`. */
  index: number;
  /** The glTF object, defaults filled in. */
  model: ResolvedObjectOf<'gltf'>;
}

/**
 * A glTF model's placement (position, uniform scale, rotation) and its asset: its id, whether the
 * preview has read it (its size), or why it cannot. Its materials are the model's own.
 */
export function InspectorModel({ index, model }: InspectorModelProps) {
  const setField = useSceneStore((s) => s.setObjectField);
  const state = useMeshLookup()(model);
  const path = `objects[${index}]`;
  const serverError = [useFieldError(path), useFieldError(`${path}.asset`)].find((e) => e !== undefined);
  const vector = (field: string, label: string, value: Vec3, hint: string, step: number) => (
    <VectorField label={label} path={`${path}.${field}`} value={value} hint={hint} step={step} onCommit={(v) => setField(index, field, v)} />
  );
  let status: string;
  if (state.status === 'ready') {
    const p = state.mesh.positions;
    const size = [0, 1, 2].map((k) => Math.abs(p[21 + k] - p[k]) * model.scale);
    status = `${size.map((s) => Number(s.toPrecision(3))).join(' × ')} m`;
  } else status = state.status === 'loading' ? 'loading…' : 'cannot be read';
  return (
    <>
      {vector('position', 'Position', model.position, 'Where the model’s origin goes (metres)', 0.1)}
      <NumberField label="Scale" path={`${path}.scale`} value={model.scale} min={0} minExclusive step={0.1} hint="Uniform scale of the model (glTF is in metres; greater than 0)" onCommit={(v) => setField(index, 'scale', v)} />
      {vector('rotation', 'Rotation', model.rotation, 'Degrees about x, y, z, applied in order XYZ (as three.js), after the scale', 5)}
      <fieldset className="inspector-group" data-testid="model-source">
        <legend>Model</legend>
        <p className="mesh-source">{`uploaded glTF ${model.asset.slice(0, 15)}…, ${status}`}</p>
        <p className="hint">Its materials and textures are the model’s own.</p>
        {state.status === 'error' && (
          <p className="field-error" role="alert">
            Cannot read the glTF: {state.message}
          </p>
        )}
        <FieldErrorMessage id={`${path}-model-error`} message={serverError} path={path} />
      </fieldset>
    </>
  );
}
