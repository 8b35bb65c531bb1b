/**
 * Pure scene edits: each takes a scene and returns a new one (the input is never changed).
 * The store wraps each in a named action that pushes one history entry; drags use the same
 * functions for their transient preview.
 */
import { newAreaLight, newLight, newMesh, newObject, resolveLight, resolveObject, resolveScene, SAMPLE_MESH_OBJ, sceneLights, SCENE_DEFAULTS } from './defaults';
import { NO_MESHES, type MeshLookup } from './meshCache';
import { meshBounds, parseObj, type Bounds } from './obj';
import { copyName, KIND_NAMES, uniqueName, withName } from './naming';
import { floorHeight, placeOnFloor } from './placement';
import { roundNumber } from './rounding';
import { objectAnchor } from './projection';
import type { DragTarget } from './selection';
import {
  LIGHT_FIELDS,
  MATERIAL_FIELDS,
  type CameraSettings,
  type ImageSettings,
  type Material,
  type MaterialType,
  type AddableType,
  type Light,
  type LightOf,
  type LightType,
  type ObjectType,
  type PlacedModel,
  type RenderSettings,
  type ResolvedLightOf,
  type Scene,
  type SceneObject,
  type Vec3,
} from './types';
import { add, length, normalize, scale } from './vec';

/** Distance a duplicate is moved from its original, so both stay visible. */
export const DUPLICATE_OFFSET: Vec3 = [0.5, 0, 0.5];

/**
 * Adds an object of a kind with its defaults, standing on the floor in front of the camera and
 * clear of the others and of the camera target (see {@link placeOnFloor}); a plane is the floor
 * itself and stays where its defaults put it.
 */
export function addObject(scene: Scene, kind: AddableType, meshes: MeshLookup = NO_MESHES): Scene {
  if (kind === 'mesh') return addMesh(scene, SAMPLE_MESH_OBJ, 1, meshes);
  const object = newObject(kind);
  object.name = uniqueName(scene, KIND_NAMES[kind], true, scene.objects.length);
  if (object.type === 'sphere') object.center = placeOnFloor(scene, object.radius!, object.radius!, meshes);
  if (object.type === 'box') object.center = placeOnFloor(scene, length(object.size!) / 2, object.size![1] / 2, meshes);
  return { ...scene, objects: [...scene.objects, object] };
}

/**
 * Adds a mesh of inline OBJ text with the given uniform scale, resting on the floor (its lowest
 * vertex on it) in front of the camera, clear of the others; at the origin if the text is not a mesh.
 */
export function addMesh(scene: Scene, obj: string, scale: number, meshes: MeshLookup = NO_MESHES): Scene {
  const mesh = newMesh(obj, scale);
  mesh.name = uniqueName(scene, KIND_NAMES.mesh, true, scene.objects.length);
  let parsed;
  try {
    parsed = parseObj(obj);
  } catch {
    return { ...scene, objects: [...scene.objects, mesh] };
  }
  const { min, max } = meshBounds({ scale }, parsed);
  const half: Vec3 = [(max[0] - min[0]) / 2, (max[1] - min[1]) / 2, (max[2] - min[2]) / 2];
  const centre = placeOnFloor(scene, Math.hypot(half[0], half[2]), half[1], meshes);
  // the bounds' centre goes to the spot found; the position is the OBJ origin
  mesh.position = [centre[0] - (min[0] + max[0]) / 2, centre[1] - half[1] - min[1], centre[2] - (min[2] + max[2]) / 2].map(roundNumber) as Vec3;
  return { ...scene, objects: [...scene.objects, mesh] };
}

/**
 * Adds an imported mesh or glTF model standing on the floor in front of the camera, clear of the
 * others: `bounds` is its box in its own coordinates (unscaled); without it, its origin stands
 * on the floor as if it were a 1 m thing.
 */
export function addModel(scene: Scene, model: PlacedModel, bounds?: Bounds, meshes: MeshLookup = NO_MESHES): Scene {
  const factor = model.scale ?? 1;
  const name = model.name ? uniqueName(scene, model.name, false) : uniqueName(scene, KIND_NAMES[model.type], true, scene.objects.length);
  const placed: PlacedModel = { ...model, name, position: [0, 0, 0], scale: factor, rotation: [0, 0, 0] };
  if (!bounds) {
    placed.position = placeOnFloor(scene, 0.5, 0, meshes);
    return { ...scene, objects: [...scene.objects, placed] };
  }
  const min = bounds.min.map((v) => v * factor);
  const max = bounds.max.map((v) => v * factor);
  const half: Vec3 = [(max[0] - min[0]) / 2, (max[1] - min[1]) / 2, (max[2] - min[2]) / 2];
  const centre = placeOnFloor(scene, Math.hypot(half[0], half[2]), half[1], meshes);
  placed.position = [centre[0] - (min[0] + max[0]) / 2, centre[1] - half[1] - min[1], centre[2] - (min[2] + max[2]) / 2].map(roundNumber) as Vec3;
  return { ...scene, objects: [...scene.objects, placed] };
}

/** Gives a mesh new inline OBJ text, dropping its `file` or `asset` (a mesh has exactly one source). */
export function setMeshObj(scene: Scene, index: number, obj: string): Scene {
  const object = scene.objects[index];
  if (object?.type !== 'mesh') return scene;
  const { file: _file, asset: _asset, ...rest } = object;
  const objects = scene.objects.map((o, i) => (i === index ? { ...rest, obj } : o));
  return { ...scene, objects };
}

/** Gives a mesh the triangles of an uploaded OBJ asset, dropping its `obj` or `file` (a mesh has exactly one source). */
export function setMeshAsset(scene: Scene, index: number, asset: string): Scene {
  const object = scene.objects[index];
  if (object?.type !== 'mesh') return scene;
  const { file: _file, obj: _obj, ...rest } = object;
  const objects = scene.objects.map((o, i) => (i === index ? { ...rest, asset } : o));
  return { ...scene, objects };
}

export function addLight(scene: Scene): Scene {
  const light = { ...newLight(), name: uniqueName(scene, 'Light', true, sceneLights(scene).length) };
  const lights = sceneLights(scene);
  if (lights.length > 0) light.position = add(light.position!, [-2 * lights.length, 0, 0]);
  return { ...scene, lights: [...lights, light] };
}

/** Height above the camera's target (or the floor, if higher) at which a new area light hangs, in metres. */
export const AREA_LIGHT_HEIGHT = 3;

/**
 * Adds an area light (its defaults written out) hanging {@link AREA_LIGHT_HEIGHT} above the camera's
 * target, a metre towards the camera, facing straight down onto the floor there (each further area
 * light 2 m further along x). Its aim is apart from the camera's target, so that in the plan views
 * each crosshair can be grabbed.
 */
export function addAreaLight(scene: Scene): Scene {
  const lights = sceneLights(scene);
  const { position: eye, lookAt: target } = resolveScene({ camera: scene.camera, objects: [] }).camera;
  const towards = normalize([eye[0] - target[0], 0, eye[2] - target[2]]);
  const step: Vec3 = length(towards) > 0 ? towards : [0, 0, 1];
  const others = lights.filter((l) => l.type === 'area').length;
  const floor = floorHeight(scene);
  const aim = add(target, [step[0] + 2 * others, 0, step[2]]).map(roundNumber) as Vec3;
  aim[1] = floor;
  const light = { ...newAreaLight([aim[0], Math.max(target[1], floor) + AREA_LIGHT_HEIGHT, aim[2]], aim), name: uniqueName(scene, 'Area light', true, lights.length) };
  return { ...scene, lights: [...lights, light] };
}

export function removeObject(scene: Scene, index: number): Scene {
  return { ...scene, objects: scene.objects.filter((_, i) => i !== index) };
}

export function removeLight(scene: Scene, index: number): Scene {
  return { ...scene, lights: sceneLights(scene).filter((_, i) => i !== index) };
}

export function duplicateObject(scene: Scene, index: number): Scene {
  const original = scene.objects[index];
  if (!original) return scene;
  const objects = [...scene.objects];
  objects.splice(index + 1, 0, withName(copyAside(original), copyName(scene, original.name, original.type)));
  return { ...scene, objects };
}

/** A copy of an object moved aside so both stay visible (a plane half a metre along its normal). */
export function copyAside(original: SceneObject): SceneObject {
  const copy = structuredClone(original);
  const resolved = resolveObject(original);
  if (copy.type === 'plane' && resolved.type === 'plane') {
    // A plane moved sideways is the same plane: move it half a metre along its normal.
    copy.point = add(resolved.point, scale(normalize(resolved.normal), 0.5));
    return copy;
  }
  return { ...copy, [anchorField(copy.type)]: add(objectAnchor(resolved), DUPLICATE_OFFSET) } as SceneObject;
}

export function duplicateLight(scene: Scene, index: number): Scene {
  const lights = sceneLights(scene);
  const original = lights[index];
  if (!original) return scene;
  const next = [...lights];
  next.splice(index + 1, 0, withName(lightAside(original), copyName(scene, original.name, original.type)));
  return { ...scene, lights: next };
}

/** A copy of a light moved aside (an area light with its aim, so it faces the same way). */
export function lightAside(original: Light): Light {
  const copy = structuredClone(original);
  const r = resolveLight(original);
  copy.position = add(r.position, DUPLICATE_OFFSET);
  if (copy.type === 'area' && r.type === 'area') copy.lookAt = add(r.lookAt, DUPLICATE_OFFSET);
  return copy;
}

/** Sets one field of an object (its geometry, or the whole `material`). */
export function setObjectField<K extends string>(scene: Scene, index: number, field: K, value: unknown): Scene {
  if (!scene.objects[index]) return scene;
  const objects = scene.objects.map((o, i) => (i === index ? ({ ...o, [field]: value } as SceneObject) : o));
  return { ...scene, objects };
}

/** Puts another object in an object's place (the 3D view's handles change several fields at once). */
export function replaceObject(scene: Scene, index: number, object: SceneObject): Scene {
  if (!scene.objects[index]) return scene;
  return { ...scene, objects: scene.objects.map((o, i) => (i === index ? object : o)) };
}

/** The field that says where an object is: a sphere's or box's centre, a plane's point, a mesh's position. */
export function anchorField(type: ObjectType): 'center' | 'point' | 'position' {
  return type === 'plane' ? 'point' : type === 'mesh' || type === 'gltf' ? 'position' : 'center';
}

/** Moves an object: a sphere's or box's centre, a plane's point, a mesh's position (nothing else changes). */
export function moveObject(scene: Scene, index: number, to: Vec3): Scene {
  const object = scene.objects[index];
  if (!object) return scene;
  return setObjectField(scene, index, anchorField(object.type), [...to]);
}

export function setMaterial(scene: Scene, index: number, material: Material): Scene {
  return setObjectField(scene, index, 'material', material);
}

/** Kinds whose colour tints reflected or transmitted light rather than colouring a surface. */
const TINTED: ReadonlySet<MaterialType> = new Set(['mirror', 'glass']);

/**
 * A material of another kind, keeping every override the new kind also takes; the colour only
 * between kinds where it means the same (a surface colour, or a mirror's or glass's tint).
 */
export function changeMaterialType(material: Material | undefined, type: MaterialType): Material {
  const fields: readonly string[] = MATERIAL_FIELDS[type];
  // A mirror's or glass's colour is a tint of what it reflects or lets through (white: none), a
  // surface colour is something else: the colour goes over only between kinds where it means the same.
  const sameColour = TINTED.has(type) === TINTED.has(material?.type ?? 'chalk');
  const kept = Object.entries(material ?? {}).filter(([k]) => k !== 'type' && fields.includes(k) && (k !== 'color' || sameColour));
  const next = { type, ...Object.fromEntries(kept) } as Material;
  return next;
}

/** A field of some kind of light: `radius` (point), `size` (area), `color` (both). */
export type LightField = { [T in LightType]: keyof LightOf<T> }[LightType];
/** The value a light field takes, on the kinds that have it. */
export type LightFieldValue<K extends LightField> = { [T in LightType]: K extends keyof LightOf<T> ? LightOf<T>[K] : never }[LightType];

/** Sets one field of a light; a field its kind does not have (a point light's `size`) changes nothing. */
export function setLightField<K extends LightField>(scene: Scene, index: number, field: K, value: LightFieldValue<K>): Scene {
  const lights = sceneLights(scene);
  const light = lights[index];
  if (!light || !(LIGHT_FIELDS[light.type] as readonly string[]).includes(field)) return scene;
  return { ...scene, lights: lights.map((l, i) => (i === index ? ({ ...l, [field]: value } as Light) : l)) };
}

export function moveLight(scene: Scene, index: number, to: Vec3): Scene {
  return setLightField(scene, index, 'position', [...to] as Vec3);
}

/** Aims an area light at a point (its `lookAt`); a point light has no aim and stays as it is. */
export function aimLight(scene: Scene, index: number, at: Vec3): Scene {
  return setLightField(scene, index, 'lookAt', [...at] as Vec3);
}

export function setCamera(scene: Scene, patch: Partial<CameraSettings>): Scene {
  return { ...scene, camera: { ...scene.camera, ...patch } };
}

export function setImage(scene: Scene, patch: Partial<ImageSettings>): Scene {
  return { ...scene, image: { ...scene.image, ...patch } };
}

export function setRender(scene: Scene, patch: Partial<RenderSettings>): Scene {
  return { ...scene, render: { ...scene.render, ...patch } };
}

/** Where a draggable thing is, with defaults filled in. */
export function positionOf(scene: Scene, target: DragTarget): Vec3 | null {
  switch (target.kind) {
    case 'object': {
      const object = scene.objects[target.index];
      if (!object) return null;
      return objectAnchor(resolveObject(object));
    }
    case 'light': {
      const light = sceneLights(scene)[target.index];
      return light ? resolveLight(light).position : null;
    }
    case 'lightAim': {
      const light = sceneLights(scene)[target.index];
      return light?.type === 'area' ? (resolveLight(light) as ResolvedLightOf<'area'>).lookAt : null;
    }
    case 'camera':
      return scene.camera?.position ?? SCENE_DEFAULTS.camera.position;
    case 'target':
      return scene.camera?.lookAt ?? SCENE_DEFAULTS.camera.lookAt;
  }
}

/** Moves whatever a drag holds to a new position. */
export function moveTarget(scene: Scene, target: DragTarget, to: Vec3): Scene {
  switch (target.kind) {
    case 'object':
      return moveObject(scene, target.index, to);
    case 'light':
      return moveLight(scene, target.index, to);
    case 'lightAim':
      return aimLight(scene, target.index, to);
    case 'camera':
      return setCamera(scene, { position: [...to] as Vec3 });
    case 'target':
      return setCamera(scene, { lookAt: [...to] as Vec3 });
  }
}

/** Moves a target by an offset from where it is now. */
export function nudgeTarget(scene: Scene, target: DragTarget, by: Vec3): Scene {
  const at = positionOf(scene, target);
  return at ? moveTarget(scene, target, add(at, by)) : scene;
}
