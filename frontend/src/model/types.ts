/**
 * The scene format (docs/scene-format.md), as TypeScript types. Every field but
 * `objects` may be left out and then takes its default (see `defaults.ts`). Polymorphic
 * elements are discriminated unions on `type`; each material kind carries only its own
 * overrides, exactly as the server's DTOs and the published JSON Schema.
 */

/** A point or direction `[x, y, z]`: metres, right-handed, y up (as three.js). */
export type Vec3 = [number, number, number];

/** An sRGB colour `"#rrggbb"`, as `<input type="color">` gives it. */
export type Color = string;

/** Squares of two colours, `size` metres a side (default 1). */
export interface CheckerTexture {
  type: 'checker';
  colors: [Color, Color];
  size?: number;
}

/** A PNG or JPEG: an uploaded `asset` id or (the command line) a `file` beside the scene; `scale` copies per unit of u, v. */
export interface ImageTexture {
  type: 'image';
  asset?: string;
  file?: string;
  scale?: [number, number];
}

export type Texture = CheckerTexture | ImageTexture;
export type TextureType = Texture['type'];

/**
 * A glTF 2.0 model (`.glb` or `.gltf`) uploaded as an asset, with its own materials, placed as a
 * mesh is: each vertex v of the model's scene goes to `position + R(rotation) · (scale · v)`.
 */
export interface GltfObject {
  type: 'gltf';
  /** The user's name for it (the engine ignores it). */
  name?: string;
  asset: string;
  /** A model file beside the scene, which only the command line reads (the editor names models by `asset`). */
  file?: string;
  position?: Vec3;
  /** Uniform scale, greater than 0. */
  scale?: number;
  rotation?: Vec3;
  /** Never given: the model brings its own materials (declared so code can read any object's `material`). */
  material?: never;
}

/** Its colour, unlit. */
export interface FlatMaterial {
  type: 'flat';
  color?: Color;
  /** A texture its colour multiplies (issue 45). */
  texture?: Texture;
}

/** Diffuse only. */
export interface ChalkMaterial {
  type: 'chalk';
  color?: Color;
  diffuse?: number;
  /** A texture its colour multiplies (issue 45). */
  texture?: Texture;
}

/** Diffuse plus a white highlight. */
export interface PlasticMaterial {
  type: 'plastic';
  color?: Color;
  diffuse?: number;
  specular?: number;
  shininess?: number;
  /** A texture its colour multiplies (issue 45). */
  texture?: Texture;
}

/** Highlight and reflection tinted by its colour. */
export interface MetalMaterial {
  type: 'metal';
  color?: Color;
  diffuse?: number;
  specular?: number;
  shininess?: number;
  reflectivity?: number;
  /** A texture its colour multiplies (issue 45). */
  texture?: Texture;
}

/** Perfect reflection, tinted. */
export interface MirrorMaterial {
  type: 'mirror';
  color?: Color;
  reflectivity?: number;
  /** A texture its colour multiplies (issue 45). */
  texture?: Texture;
}

/** Refraction with an index of refraction, Fresnel reflection; its colour tints the light. */
export interface GlassMaterial {
  type: 'glass';
  color?: Color;
  ior?: number;
  specular?: number;
  shininess?: number;
  /** A texture its colour multiplies (issue 45). */
  texture?: Texture;
}

export type Material =
  | FlatMaterial
  | ChalkMaterial
  | PlasticMaterial
  | MetalMaterial
  | MirrorMaterial
  | GlassMaterial;
export type MaterialType = Material['type'];
/** The material of one kind, e.g. `MaterialOf<'glass'>` is {@link GlassMaterial}. */
export type MaterialOf<T extends MaterialType> = Extract<Material, { type: T }>;

export interface Sphere {
  type: 'sphere';
  /** The user's name for it (the engine ignores it). */
  name?: string;
  center?: Vec3;
  radius?: number;
  material?: Material;
}

/** A box: centre, full edge lengths, rotation in degrees about x, y, z (three.js order XYZ). */
export interface Box {
  type: 'box';
  /** The user's name for it (the engine ignores it). */
  name?: string;
  center?: Vec3;
  size?: Vec3;
  rotation?: Vec3;
  material?: Material;
}

/** An infinite plane through `point` with the given normal (any non-zero length). */
export interface Plane {
  type: 'plane';
  /** The user's name for it (the engine ignores it). */
  name?: string;
  point?: Vec3;
  normal?: Vec3;
  material?: Material;
}

/**
 * A triangle mesh from Wavefront OBJ: exactly one of `obj` (the OBJ text itself), `file` (a
 * name the CLI reads beside the scene file; the server knows only the meshes shipped with its
 * examples) and `asset` (the id, sha256-<hex>, of OBJ bytes uploaded with POST /api/assets). Each OBJ vertex v is placed at `position + R(rotation) · (scale · v)`: a uniform
 * scale, then the rotation in degrees (three.js order XYZ), then the move, as a three.js Object3D.
 */
export interface MeshObject {
  type: 'mesh';
  /** The user's name for it (the engine ignores it). */
  name?: string;
  obj?: string;
  file?: string;
  asset?: string;
  position?: Vec3;
  /** Uniform scale, greater than 0. */
  scale?: number;
  rotation?: Vec3;
  material?: Material;
}

/** The fields naming where a mesh's triangles come from (no defaults: exactly one is given). */
export type MeshSourceField = 'obj' | 'file' | 'asset';

export type SceneObject = Sphere | Box | Plane | MeshObject | GltfObject;
/** An object placed as a three.js Object3D (position, uniform scale, rotation), whose shape is loaded: a mesh or a glTF model. */
export type PlacedModel = MeshObject | GltfObject;
export type ObjectType = SceneObject['type'];
export type ObjectOf<T extends ObjectType> = Extract<SceneObject, { type: T }>;

/** A width and a height `[w, h]` in metres. */
export type Size2 = [number, number];

/**
 * A point light; without `falloff` its irradiance does not depend on distance. With a `radius`
 * above 0 it is a sphere of that radius (metres): soft shadows, and seen by camera and mirrors.
 */
export interface PointLight {
  type: 'point';
  /** The user's name for it (the engine ignores it). */
  name?: string;
  position?: Vec3;
  color?: Color;
  intensity?: number;
  falloff?: boolean;
  /** Metres, finite and at least 0; 0 (the default) is a point. */
  radius?: number;
}

/**
 * A rectangular light, as three.js's RectAreaLight: centred at `position`, its front facing
 * `lookAt` (which must differ from `position`), `size` = [width, height] in metres (each greater
 * than 0) along its own x and y axes (see `areaLightFrame`). It emits from its front only, unless
 * `twoSided`.
 */
export interface AreaLight {
  type: 'area';
  /** The user's name for it (the engine ignores it). */
  name?: string;
  position?: Vec3;
  size?: Size2;
  lookAt?: Vec3;
  color?: Color;
  intensity?: number;
  falloff?: boolean;
  twoSided?: boolean;
}

export type Light = PointLight | AreaLight;
export type LightType = Light['type'];
/** The light of one kind, e.g. `LightOf<'area'>` is {@link AreaLight}. */
export type LightOf<T extends LightType> = Extract<Light, { type: T }>;

export type ImageFormat = 'png' | 'jpg';
/** Where a pixel's samples go (the server's Sampler.names(), simplest first). */
export type SamplerName = 'regular' | 'random' | 'jittered' | 'multijittered' | 'sobol';

export interface ImageSettings {
  width?: number;
  height?: number;
  format?: ImageFormat;
  /** JPEG quality in [0, 1]. */
  quality?: number;
}

/** A perspective camera; `fov` is the vertical field of view in degrees (as three.js). */
export interface CameraSettings {
  position?: Vec3;
  lookAt?: Vec3;
  up?: Vec3;
  fov?: number;
}

export interface RenderSettings {
  sampler?: SamplerName;
  /** Samples per pixel; with adaptive sampling, the most a pixel takes. */
  samples?: number;
  maxDepth?: number;
  seed?: number;
  /**
   * Adaptive sampling: a pixel stops taking samples once its error is within this fraction of (the
   * square root of) its brightness. With sobol it takes one sample and stops there if its 3x3
   * neighbourhood agrees, else walks on along its sequence; with the others, batches of 4, at least
   * 8. 0 (or absent): off; at one sample a pixel there is nothing to adapt. In [0, 1].
   */
  adaptive?: number;
}

/** A whole scene file. */
export interface Scene {
  version?: number;
  name?: string;
  image?: ImageSettings;
  camera?: CameraSettings;
  background?: Color;
  ambient?: number;
  render?: RenderSettings;
  /** Left out: one white light at [5,8,5]; `[]`: no lights. */
  lights?: Light[];
  objects: SceneObject[];
}

/** Every field present: what the renderer will use. */
type Complete<T> = { [K in keyof T]-?: Exclude<T[K], undefined> };

/** A material's overrides, which all have defaults (its texture has none: absent, the colour alone). */
export type MaterialDefaultsOf<T extends MaterialType> = Complete<Omit<MaterialOf<T>, 'texture'>>;
export type ResolvedMaterial = {
  [T in MaterialType]: MaterialDefaultsOf<T> & Pick<MaterialOf<T>, 'texture'>;
}[MaterialType];
export type ResolvedObject = {
  [T in ObjectType]: Complete<Omit<ObjectOf<T>, 'material' | MeshSourceField | 'name'>> &
    Pick<ObjectOf<T>, Extract<keyof ObjectOf<T>, MeshSourceField | 'name'>> & { material: ResolvedMaterial };
  // a glTF model has its own materials: its resolved `material` is the default, never shown
}[ObjectType];
/** A resolved object of one kind, e.g. `ResolvedObjectOf<'mesh'>`. */
export type ResolvedObjectOf<T extends ObjectType> = Extract<ResolvedObject, { type: T }>;
export type ResolvedLight = {
  [T in LightType]: Complete<Omit<LightOf<T>, 'name'>> & Pick<LightOf<T>, Extract<keyof LightOf<T>, 'name'>>;
}[LightType];
/** A resolved light of one kind, e.g. `ResolvedLightOf<'area'>`. */
export type ResolvedLightOf<T extends LightType> = Extract<ResolvedLight, { type: T }>;

/** A scene with every default filled in (for display; files keep what the user wrote). */
export interface ResolvedScene {
  version: number;
  name: string;
  image: Complete<ImageSettings>;
  camera: Complete<CameraSettings>;
  background: Color;
  ambient: number;
  render: Complete<RenderSettings>;
  lights: ResolvedLight[];
  objects: ResolvedObject[];
}

/**
 * The field names of each kind, checked against the types at compile time (a missing or
 * extra name is a type error), so a test can compare them with the server's JSON Schema.
 */
function fieldsOf<T>() {
  return <const K extends readonly (keyof T)[]>(
    keys: K & ([Exclude<keyof T, K[number]>] extends [never] ? unknown : { missing: Exclude<keyof T, K[number]> }),
  ): K => keys;
}

export const OBJECT_FIELDS = {
  sphere: fieldsOf<Sphere>()(['type', 'name', 'center', 'radius', 'material']),
  box: fieldsOf<Box>()(['type', 'name', 'center', 'size', 'rotation', 'material']),
  plane: fieldsOf<Plane>()(['type', 'name', 'point', 'normal', 'material']),
  mesh: fieldsOf<MeshObject>()(['type', 'name', 'obj', 'file', 'asset', 'position', 'scale', 'rotation', 'material']),
  gltf: fieldsOf<Omit<GltfObject, 'material'>>()(['type', 'name', 'asset', 'file', 'position', 'scale', 'rotation']),
} as const;

export const MATERIAL_FIELDS = {
  flat: fieldsOf<FlatMaterial>()(['type', 'color', 'texture']),
  chalk: fieldsOf<ChalkMaterial>()(['type', 'color', 'diffuse', 'texture']),
  plastic: fieldsOf<PlasticMaterial>()(['type', 'color', 'diffuse', 'specular', 'shininess', 'texture']),
  metal: fieldsOf<MetalMaterial>()(['type', 'color', 'diffuse', 'specular', 'shininess', 'reflectivity', 'texture']),
  mirror: fieldsOf<MirrorMaterial>()(['type', 'color', 'reflectivity', 'texture']),
  glass: fieldsOf<GlassMaterial>()(['type', 'color', 'ior', 'specular', 'shininess', 'texture']),
} as const;

export const TEXTURE_FIELDS = {
  checker: fieldsOf<CheckerTexture>()(['type', 'colors', 'size']),
  image: fieldsOf<ImageTexture>()(['type', 'asset', 'file', 'scale']),
} as const;

export const LIGHT_FIELDS = {
  point: fieldsOf<PointLight>()(['type', 'name', 'position', 'color', 'intensity', 'falloff', 'radius']),
  area: fieldsOf<AreaLight>()(['type', 'name', 'position', 'size', 'lookAt', 'color', 'intensity', 'falloff', 'twoSided']),
} as const;

export const SCENE_FIELDS = fieldsOf<Scene>()([
  'version', 'name', 'image', 'camera', 'background', 'ambient', 'render', 'lights', 'objects',
]);
export const IMAGE_FIELDS = fieldsOf<ImageSettings>()(['width', 'height', 'format', 'quality']);
export const CAMERA_FIELDS = fieldsOf<CameraSettings>()(['position', 'lookAt', 'up', 'fov']);
export const RENDER_FIELDS = fieldsOf<RenderSettings>()(['sampler', 'samples', 'maxDepth', 'seed', 'adaptive']);

export const OBJECT_TYPES = Object.keys(OBJECT_FIELDS) as ObjectType[];
/** The kinds that can be added without a file (a glTF model needs its uploaded asset). */
export type AddableType = Exclude<ObjectType, 'gltf'>;
export const ADDABLE_TYPES = OBJECT_TYPES.filter((t): t is AddableType => t !== 'gltf');
export const MATERIAL_TYPES = Object.keys(MATERIAL_FIELDS) as MaterialType[];
export const LIGHT_TYPES = Object.keys(LIGHT_FIELDS) as LightType[];
