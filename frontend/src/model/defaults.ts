/**
 * The defaults of the scene format, the same values as the table in docs/scene-format.md, the server's
 * SceneDefaults and the engine's MaterialDefaults; and {@link resolveScene}, which fills them
 * in for display.
 */
import type {
  AddableType,
  Material,
  MaterialDefaultsOf,
  MeshObject,
  MeshSourceField,
  MaterialType,
  ObjectOf,
  AreaLight,
  Light,
  ObjectType,
  PointLight,
  ResolvedLight,
  ResolvedLightOf,
  ResolvedMaterial,
  ResolvedObject,
  ResolvedScene,
  Scene,
  SceneObject,
  Vec3,
} from './types';

export const FORMAT_VERSION = 1;

/** Every scene-level default (objects and lights have their own below). */
export const SCENE_DEFAULTS: Omit<ResolvedScene, 'lights' | 'objects'> = {
  version: FORMAT_VERSION,
  name: 'render',
  image: { width: 800, height: 600, format: 'png', quality: 0.92 },
  camera: { position: [0, 2, 8], lookAt: [0, 0, 0], up: [0, 1, 0], fov: 50 },
  background: '#20232a',
  ambient: 0.08,
  render: { sampler: 'sobol', samples: 16, maxDepth: 6, seed: 0, adaptive: 0.05 },
};

/**
 * A point light's defaults; without its radius (0: a point) also the one light a scene without a
 * `lights` field has.
 */
export const LIGHT_DEFAULTS: ResolvedLightOf<'point'> = {
  type: 'point',
  position: [5, 8, 5],
  color: '#ffffff',
  intensity: 1,
  falloff: false,
  radius: 0,
};

/** An area light's defaults: a metre square where a point light stands by default, facing the origin. */
export const AREA_LIGHT_DEFAULTS: ResolvedLightOf<'area'> = {
  type: 'area',
  position: [5, 8, 5],
  size: [1, 1],
  lookAt: [0, 0, 0],
  color: '#ffffff',
  intensity: 1,
  falloff: false,
  twoSided: false,
};

/** The geometry defaults of each object kind (a mesh's `obj` or `file` has none: one is required). */
export const OBJECT_DEFAULTS: { [T in ObjectType]: Required<Omit<ObjectOf<T>, 'material' | MeshSourceField | 'name'>> } = {
  sphere: { type: 'sphere', center: [0, 1, 0], radius: 1 },
  box: { type: 'box', center: [0, 0.5, 0], size: [1, 1, 1], rotation: [0, 0, 0] },
  plane: { type: 'plane', point: [0, 0, 0], normal: [0, 1, 0] },
  mesh: { type: 'mesh', position: [0, 0, 0], scale: 1, rotation: [0, 0, 0] },
  gltf: { type: 'gltf', position: [0, 0, 0], scale: 1, rotation: [0, 0, 0] },
};

/** The OBJ of a mesh added without a file: a regular octahedron with its corners 1 m from its centre. */
export const SAMPLE_MESH_OBJ = [
  '# octahedron',
  'v 1 0 0', 'v -1 0 0', 'v 0 1 0', 'v 0 -1 0', 'v 0 0 1', 'v 0 0 -1',
  'f 1 3 5', 'f 2 5 3', 'f 1 5 4', 'f 1 6 3', 'f 2 4 5', 'f 2 3 6', 'f 1 4 6', 'f 2 6 4',
  '',
].join('\n');

/** A missing material is grey chalk. */
export const DEFAULT_MATERIAL_TYPE: MaterialType = 'chalk';

const GREY = '#cccccc';
const WHITE = '#ffffff';

/** Each material kind's defaults (engine MaterialDefaults). */
export const MATERIAL_DEFAULTS: { [T in MaterialType]: MaterialDefaultsOf<T> } = {
  flat: { type: 'flat', color: GREY },
  chalk: { type: 'chalk', color: GREY, diffuse: 0.9 },
  plastic: { type: 'plastic', color: GREY, diffuse: 0.8, specular: 0.5, shininess: 60 },
  metal: { type: 'metal', color: GREY, diffuse: 0.15, specular: 0.8, shininess: 120, reflectivity: 0.5 },
  mirror: { type: 'mirror', color: WHITE, reflectivity: 1 },
  glass: { type: 'glass', color: WHITE, ior: 1.5, specular: 0.6, shininess: 250 },
};

const copy = (v: Vec3): Vec3 => [v[0], v[1], v[2]];

/** A material with every override of its kind filled in. */
export function resolveMaterial(material: Material | undefined): ResolvedMaterial {
  const kind = material?.type ?? DEFAULT_MATERIAL_TYPE;
  return { ...MATERIAL_DEFAULTS[kind], ...definedOnly(material ?? {}) } as ResolvedMaterial;
}

/** An object with its geometry defaults and its resolved material. */
export function resolveObject(object: SceneObject): ResolvedObject {
  const defaults = OBJECT_DEFAULTS[object.type];
  const geometry = cloneVectors({ ...defaults, ...definedOnly(object) });
  return { ...geometry, material: resolveMaterial(object.material) } as ResolvedObject;
}

/** A light with the defaults of its kind filled in. */
export function resolveLight(light: Light): ResolvedLight {
  const defaults: ResolvedLight = light.type === 'area' ? AREA_LIGHT_DEFAULTS : LIGHT_DEFAULTS;
  return cloneVectors({ ...defaults, ...definedOnly(light) } as ResolvedLight);
}

/** The lights a scene really has: its own, or the default light when the field is left out. */
export function sceneLights(scene: Scene): Light[] {
  return scene.lights ?? [newLight()];
}

/** The scene with every default filled in; the input is not changed. */
export function resolveScene(scene: Scene): ResolvedScene {
  const d = SCENE_DEFAULTS;
  return {
    version: scene.version ?? d.version,
    name: scene.name ?? d.name,
    image: { ...d.image, ...definedOnly(scene.image ?? {}) },
    camera: cloneVectors({ ...d.camera, ...definedOnly(scene.camera ?? {}) }),
    background: scene.background ?? d.background,
    ambient: scene.ambient ?? d.ambient,
    render: { ...d.render, ...definedOnly(scene.render ?? {}) },
    lights: sceneLights(scene).map(resolveLight),
    objects: scene.objects.map(resolveObject),
  };
}

/** The image's width / height, as the engine's camera uses it. */
export function imageAspect(scene: Scene): number {
  const { width, height } = resolveScene({ ...scene, objects: [] }).image;
  return width / height;
}

/** A new object of a kind as the toolbar adds it: its defaults written out (a mesh: the sample octahedron). */
export function newObject(kind: AddableType): SceneObject {
  if (kind === 'mesh') return newMesh(SAMPLE_MESH_OBJ, 1);
  const object = cloneVectors({ ...OBJECT_DEFAULTS[kind] }) as SceneObject;
  const material: Material = kind === 'plane' ? { type: 'chalk', color: '#c8c0b0' } : { type: 'plastic', color: '#4f8fd6' };
  return { ...object, material } as SceneObject;
}

/** A new mesh of inline OBJ text at the origin, with the given uniform scale. */
export function newMesh(obj: string, scale: number): MeshObject {
  const { position, rotation } = OBJECT_DEFAULTS.mesh;
  return { type: 'mesh', obj, position: copy(position), scale, rotation: copy(rotation), material: { type: 'plastic', color: '#4f8fd6' } };
}

/**
 * A new point light, written out in full but for its radius: a radius of 0 is left out, so the file
 * stays what a point light always was.
 */
export function newLight(): PointLight {
  const { radius: _radius, ...light } = LIGHT_DEFAULTS;
  return { ...light, position: copy(light.position) };
}

/** A new area light aimed at `lookAt` from `position`, written out in full. */
export function newAreaLight(position: Vec3, lookAt: Vec3): AreaLight {
  return { ...AREA_LIGHT_DEFAULTS, position: copy(position), lookAt: copy(lookAt), size: [...AREA_LIGHT_DEFAULTS.size] };
}

/** A blank scene for "New": no objects, the default light written out. */
export function blankScene(): Scene {
  return { version: FORMAT_VERSION, name: 'untitled', lights: [newLight()], objects: [] };
}

function definedOnly<T extends object>(value: T): Partial<T> {
  return Object.fromEntries(Object.entries(value).filter(([, v]) => v !== undefined)) as Partial<T>;
}

function cloneVectors<T extends object>(value: T): T {
  return Object.fromEntries(
    Object.entries(value).map(([k, v]) => [k, Array.isArray(v) ? [...v] : v]),
  ) as T;
}
