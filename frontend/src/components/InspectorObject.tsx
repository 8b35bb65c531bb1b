import { resolveObject } from '../model/defaults';
import * as edits from '../model/edits';
import type { Material, Vec3 } from '../model/types';
import { selectDisplayScene, useSceneStore } from '../store/sceneStore';
import { InspectorMaterial } from './InspectorMaterial';
import { InspectorMesh } from './InspectorMesh';
import { InspectorModel } from './InspectorModel';
import { NumberField } from './fields/NumberField';
import { VectorField } from './fields/VectorField';
import { NameField } from './fields/NameField';
import { labelOf, OBJECT_HINTS } from './labels';

/** Props of {@link InspectorObject}. */
export interface InspectorObjectProps {
  /** Index of the object in `scene.objects`. */
  index: number;
}

/** Fields of one object: its geometry (defaults shown where unset) and its material. */
export function InspectorObject({ index }: InspectorObjectProps) {
  const object = useSceneStore((s) => selectDisplayScene(s).objects[index]);
  const setField = useSceneStore((s) => s.setObjectField);
  const setMaterial = useSceneStore((s) => s.setMaterial);
  const setMaterialType = useSceneStore((s) => s.setMaterialType);
  const setPreview = useSceneStore((s) => s.setPreview);
  const cancelPreview = useSceneStore((s) => s.cancelPreview);
  if (!object) return null;
  const r = resolveObject(object);
  const path = `objects[${index}]`;
  const vector = (field: string, label: string, value: Vec3, hint: string, min?: number, step = 0.1, minExclusive = false) => (
    <VectorField
      label={label}
      path={`${path}.${field}`}
      value={value}
      hint={hint}
      min={min}
      minExclusive={minExclusive}
      step={step}
      onCommit={(v) => setField(index, field, v)}
    />
  );
  const previewMaterial = (material: Material) =>
    setPreview(edits.setMaterial(useSceneStore.getState().scene, index, material));

  return (
    <section className="inspector-section" aria-label={`${labelOf(object, index)} properties`} data-testid="inspector-object">
      <h3 title={OBJECT_HINTS[r.type]}>{labelOf(object, index)}</h3>
      <NameField path={`${path}.name`} value={object.name} onCommit={(name) => setField(index, 'name', name)} />
      {r.type === 'sphere' && (
        <>
          {vector('center', 'Center', r.center, 'Centre of the sphere (metres)')}
          <NumberField
            label="Radius"
            path={`${path}.radius`}
            value={r.radius}
            min={0}
            minExclusive
            step={0.05}
            hint="Radius in metres (greater than 0)"
            onCommit={(v) => setField(index, 'radius', v)}
          />
        </>
      )}
      {r.type === 'box' && (
        <>
          {vector('center', 'Center', r.center, 'Centre of the box (metres)')}
          {vector('size', 'Size', r.size, 'Full edge lengths along the box’s own x, y, z (metres)', 0, 0.1, true)}
          {vector('rotation', 'Rotation', r.rotation, 'Degrees about x, y, z, applied in order XYZ (as three.js)', undefined, 5)}
        </>
      )}
      {r.type === 'mesh' && <InspectorMesh index={index} mesh={r} />}
      {r.type === 'gltf' && <InspectorModel index={index} model={r} />}
      {r.type === 'plane' && (
        <>
          {vector('point', 'Point', r.point, 'Any point on the plane (metres)')}
          {vector('normal', 'Normal', r.normal, 'The direction the plane faces (any non-zero length)')}
        </>
      )}
      {r.type !== 'gltf' && <InspectorMaterial
        path={`${path}.material`}
        material={object.material}
        onTypeChange={(t) => setMaterialType(index, t)}
        onChange={(m) => setMaterial(index, m)}
        onPreview={previewMaterial}
        onPreviewEnd={cancelPreview}
      />}
    </section>
  );
}
