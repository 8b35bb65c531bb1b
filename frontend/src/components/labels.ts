/** Display names and tooltips shared by the inspector, the outline, the toolbar and the views. */
import type { MeshState } from '../model/meshCache';
import { idNumber, idOf } from '../model/identity';
import { KIND_NAMES } from '../model/naming';
import type { Light, LightType, MaterialType, ObjectType, Scene, SceneObject } from '../model/types';

export const OBJECT_LABELS: Record<ObjectType, string> = KIND_NAMES;

export const OBJECT_HINTS: Record<ObjectType, string> = {
  sphere: 'A sphere: centre and radius',
  box: 'A box: centre, full edge lengths and rotation in degrees (x, y, z applied in order XYZ)',
  plane: 'An infinite plane through a point, facing its normal (e.g. a floor)',
  mesh: 'A triangle mesh from a Wavefront OBJ file: position, uniform scale and rotation in degrees (x, y, z applied in order XYZ)',
  gltf: 'A glTF 2.0 model with its own materials: position, uniform scale and rotation in degrees (x, y, z applied in order XYZ)',
};

export const MATERIAL_LABELS: Record<MaterialType, string> = {
  flat: 'Flat',
  chalk: 'Chalk',
  plastic: 'Plastic',
  metal: 'Metal',
  mirror: 'Mirror',
  glass: 'Glass',
};

export const MATERIAL_HINTS: Record<MaterialType, string> = {
  flat: 'Its colour, unlit',
  chalk: 'Diffuse only (matte)',
  plastic: 'Diffuse plus a white highlight',
  metal: 'Highlight and reflection tinted by its colour',
  mirror: 'Perfect reflection, tinted',
  glass: 'Refraction and Fresnel reflection; its colour tints the light that enters',
};

/** Number-field settings of each material override. */
export const OVERRIDE_FIELDS: Record<string, { label: string; min: number; max: number; step: number; hint: string }> = {
  diffuse: { label: 'Diffuse', min: 0, max: 1, step: 0.05, hint: 'How much light the surface scatters (0–1)' },
  specular: { label: 'Specular', min: 0, max: 1, step: 0.05, hint: 'Strength of the highlight (0–1)' },
  shininess: { label: 'Shininess', min: 1, max: 10000, step: 10, hint: 'Highlight exponent: higher is a smaller, sharper highlight' },
  reflectivity: { label: 'Reflectivity', min: 0, max: 1, step: 0.05, hint: 'Share of light reflected (0–1)' },
  ior: { label: 'Index of refraction', min: 1, max: 4, step: 0.01, hint: 'Glass about 1.5, water 1.33, diamond 2.42' },
};

/** "Sphere 2 · mirror" style name of an object. */
export function objectName(type: ObjectType, index: number): string {
  return `${OBJECT_LABELS[type]} ${index + 1}`;
}

/**
 * How an object is named everywhere: by the user's name (`Sphere "ball"`), else by its kind and the
 * number of its stable id (`Sphere 2`, which deleting another object does not change).
 */
export function objectLabel(scene: Scene, index: number): string {
  const object = scene.objects[index];
  return object ? labelOf(object, index) : `Object ${index + 1}`;
}

/** What each kind of light is called. */
export const LIGHT_LABELS: Record<LightType, string> = { point: 'Light', area: 'Area light' };

/** The user's name of an object or light, if it has one (an area light has no name field). */
export function nameOf(item: SceneObject | Light): string | undefined {
  return 'name' in item ? item.name : undefined;
}

/**
 * An object's or light's label: its name in quotes after its kind, or its kind and id number; a name
 * the editor gave it (`Sphere 3`) as it is.
 */
export function labelOf(item: SceneObject | Light, index: number): string {
  const kind = item.type === 'point' || item.type === 'area' ? LIGHT_LABELS[item.type] : OBJECT_LABELS[item.type];
  const name = nameOf(item);
  if (name && new RegExp(`^${kind} \\d+$`).test(name)) return name;
  if (name) return `${kind} "${name}"`;
  return `${kind} ${idNumber(idOf(item)) ?? index + 1}`;
}

/** A light's label (`Light 1`, `Light "key"`). */
export function lightLabel(lights: Light[], index: number): string {
  const light = lights[index];
  return light ? labelOf(light, index) : `Light ${index + 1}`;
}

/** "4,800 triangles", "1 triangle". */
export function triangleCountLabel(count: number): string {
  return `${count.toLocaleString('en-US')} ${count === 1 ? 'triangle' : 'triangles'}`;
}

/** A mesh's name with what is known of its triangles: "Mesh 3 (4,800 triangles)", "Mesh 3 (loading…)". */
export function meshName(label: string, state: MeshState, format = 'OBJ'): string {
  const loading = state.status === 'loading' && state.progress ? `reading… ${Math.round(100 * state.progress)}%` : 'loading…';
  // a glTF model's state holds its bounding box, not its triangles
  const ready = state.status === 'ready' && format === 'glTF' ? 'glTF' : state.status === 'ready' ? triangleCountLabel(state.mesh.triangleCount) : '';
  const detail = state.status === 'ready' ? ready : state.status === 'loading' ? loading : `${format} error`;
  return `${label} (${detail})`;
}
