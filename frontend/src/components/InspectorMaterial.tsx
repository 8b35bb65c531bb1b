import { resolveMaterial } from '../model/defaults';
import { MATERIAL_FIELDS, MATERIAL_TYPES, type Material, type MaterialType, type ResolvedMaterial } from '../model/types';
import { ColorField } from './fields/ColorField';
import { NumberField } from './fields/NumberField';
import { SelectField } from './fields/SelectField';
import { MATERIAL_HINTS, MATERIAL_LABELS, OVERRIDE_FIELDS } from './labels';

/** Props of {@link InspectorMaterial}. */
export interface InspectorMaterialProps {
  /** JSON path of the material, e.g. `objects[2].material`. */
  path: string;
  /** The material as the scene has it (undefined: the default grey chalk). */
  material: Material | undefined;
  /** Called with a new material kind. */
  onTypeChange: (type: MaterialType) => void;
  /** Called with the whole new material after one override changed. */
  onChange: (material: Material) => void;
  /** Called with a material to show while the colour picker is open (not history). */
  onPreview: (material: Material) => void;
  onPreviewEnd: () => void;
}

/** The material picker and the overrides of the chosen kind (showing defaults where unset). */
export function InspectorMaterial({ path, material, onTypeChange, onChange, onPreview, onPreviewEnd }: InspectorMaterialProps) {
  // the overrides shown here; a texture is kept as it is by every edit (set copies the material)
  const resolved = withoutTexture(resolveMaterial(material)) as Record<string, number | string>;
  const current: Material = material ?? { type: resolved.type as MaterialType };
  const kind = current.type;
  const set = (field: string, value: unknown) => ({ ...current, [field]: value }) as Material;
  return (
    <fieldset className="inspector-group">
      <legend>Material</legend>
      <SelectField
        label="Material type"
        path={`${path}.type`}
        value={kind}
        hint={MATERIAL_HINTS[kind]}
        options={MATERIAL_TYPES.map((t) => ({ value: t, label: MATERIAL_LABELS[t], hint: MATERIAL_HINTS[t] }))}
        onCommit={(t) => onTypeChange(t as MaterialType)}
      />
      <ColorField
        label="Color"
        path={`${path}.color`}
        value={String(resolved.color)}
        hint="The surface colour (sRGB)"
        onCommit={(c) => onChange(set('color', c))}
        onPreview={(c) => onPreview(set('color', c))}
        onPreviewEnd={onPreviewEnd}
      />
      {MATERIAL_FIELDS[kind]
        .filter((f) => f !== 'type' && f !== 'color' && f !== 'texture')
        .map((field) => {
          const spec = OVERRIDE_FIELDS[field];
          return (
            <NumberField
              key={field}
              label={spec.label}
              path={`${path}.${field}`}
              value={Number(resolved[field])}
              min={spec.min}
              max={spec.max}
              step={spec.step}
              hint={spec.hint}
              onCommit={(v) => onChange(set(field, v))}
            />
          );
        })}
    </fieldset>
  );
}

/** A resolved material's overrides: all but its texture. */
function withoutTexture(m: ResolvedMaterial): Omit<ResolvedMaterial, 'texture'> {
  const overrides: Partial<ResolvedMaterial> = { ...m };
  delete overrides.texture;
  return overrides as Omit<ResolvedMaterial, 'texture'>;
}
