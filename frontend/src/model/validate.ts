/**
 * Checks that an unknown JSON value has the shape of a scene before the editor loads it:
 * known fields only, `type` of every polymorphic element known, vectors of three finite
 * numbers, colours `#rrggbb`, numbers as numbers. Value ranges are the server's business, but
 * for a mesh, whose triangles the editor reads itself: exactly one of `obj`, `file` and `asset`,
 * and a `scale` greater than 0 (as the server's rules); asset ids of the form `sha256-<hex>`.
 */
import { FORMAT_VERSION } from './defaults';
import {
  CAMERA_FIELDS,
  IMAGE_FIELDS,
  LIGHT_FIELDS,
  MATERIAL_FIELDS,
  OBJECT_FIELDS,
  RENDER_FIELDS,
  SCENE_FIELDS,
  TEXTURE_FIELDS,
  type Scene,
} from './types';
import { isRecord } from '../util/json';

/** One problem, named by its JSON path (`objects[2].radius`). */
export interface ShapeError {
  path: string;
  message: string;
}

export type ParseResult = { ok: true; scene: Scene } | { ok: false; errors: ShapeError[] };

type Check = (value: unknown, path: string, errors: ShapeError[]) => void;


const number: Check = (v, path, errors) => {
  if (typeof v !== 'number' || !Number.isFinite(v)) errors.push({ path, message: 'must be a finite number' });
};
const integer: Check = (v, path, errors) => {
  if (typeof v !== 'number' || !Number.isInteger(v)) errors.push({ path, message: 'must be a whole number' });
};
const string: Check = (v, path, errors) => {
  if (typeof v !== 'string') errors.push({ path, message: 'must be a string' });
};
const boolean: Check = (v, path, errors) => {
  if (typeof v !== 'boolean') errors.push({ path, message: 'must be true or false' });
};
const color: Check = (v, path, errors) => {
  if (typeof v !== 'string' || !/^#[0-9a-fA-F]{6}$/.test(v)) {
    errors.push({ path, message: 'must be a colour of the form #rrggbb' });
  }
};
const vector: Check = (v, path, errors) => {
  if (!Array.isArray(v) || v.length !== 3) {
    errors.push({ path, message: 'must be a list of three numbers [x, y, z]' });
    return;
  }
  v.forEach((c, i) => number(c, `${path}[${i}]`, errors));
};
const size2: Check = (v, path, errors) => {
  if (!Array.isArray(v) || v.length !== 2) {
    errors.push({ path, message: 'must be a list of two numbers [width, height]' });
    return;
  }
  v.forEach((c, i) => number(c, `${path}[${i}]`, errors));
};
const oneOf =
  (...allowed: string[]): Check =>
  (v, path, errors) => {
    if (typeof v !== 'string' || !allowed.includes(v)) {
      errors.push({ path, message: `must be one of ${allowed.map((a) => `"${a}"`).join(', ')}` });
    }
  };

/** Checks a record against the checks of its fields; any other field is an error. */
function record(fields: readonly string[], checks: Record<string, Check>): Check {
  return (v, path, errors) => {
    if (!isRecord(v)) {
      errors.push({ path, message: 'must be an object {…}' });
      return;
    }
    for (const [key, value] of Object.entries(v)) {
      const where = path ? `${path}.${key}` : key;
      if (!fields.includes(key)) {
        errors.push({ path: where, message: `is not a known field (known: ${fields.join(', ')})` });
      } else if (value !== undefined) {
        checks[key]?.(value, where, errors);
      }
    }
  };
}

/** A polymorphic element: picks the check by its `type`. */
function byType(kinds: Record<string, Check>): Check {
  return (v, path, errors) => {
    if (!isRecord(v)) {
      errors.push({ path, message: 'must be an object {…}' });
    } else if (typeof v.type !== 'string' || !(v.type in kinds)) {
      const known = Object.keys(kinds).map((k) => `"${k}"`).join(', ');
      errors.push({ path: `${path}.type`, message: `must be one of ${known}` });
    } else {
      kinds[v.type](v, path, errors);
    }
  };
}

const list =
  (item: Check): Check =>
  (v, path, errors) => {
    if (!Array.isArray(v)) errors.push({ path, message: 'must be a list […]' });
    else v.forEach((x, i) => item(x, `${path}[${i}]`, errors));
  };

function positiveNumber(v: unknown, path: string, errors: ShapeError[]): void {
  if (typeof v !== 'number' || !Number.isFinite(v) || v <= 0) errors.push({ path, message: 'must be a finite number greater than 0' });
}
const positive: Check = positiveNumber;

/** A mesh names its triangles by exactly one of `obj`, `file` and `asset` (the message goes on the object, as the server's). */
const meshSource: Check = (v, path, errors) => {
  if (!isRecord(v)) return;
  const sources = [v.obj, v.file, v.asset].filter((s) => s !== undefined).length;
  if (sources !== 1) {
    errors.push({ path, message: sources > 1 ? 'give the mesh one of "obj", "file" and "asset", not more' : 'a mesh needs its OBJ text in "obj", a "file" name or an "asset" id' });
  }
};

/** A glTF model names exactly one of its asset id (the editor's) and a file beside the scene (the command line's). */
const modelSource: Check = (v, path, errors) => {
  if (!isRecord(v)) return;
  if (v.asset !== undefined && v.file !== undefined) errors.push({ path, message: 'give the model one of "asset" and "file", not both' });
  else if (v.asset === undefined && v.file === undefined) errors.push({ path: `${path}.asset`, message: 'is required' });
};

/** An image texture names exactly one of its asset id and a file beside the scene. */
const imageSource: Check = (v, path, errors) => {
  if (!isRecord(v)) return;
  if (v.asset !== undefined && v.file !== undefined) errors.push({ path, message: 'give the image one of "asset" and "file", not both' });
  else if (v.asset === undefined && v.file === undefined) errors.push({ path: `${path}.asset`, message: 'is required' });
};

/** An asset id as the server gives it: `sha256-` and 64 lower-case hex digits. */
export const ASSET_ID = /^sha256-[0-9a-f]{64}$/;
const assetId: Check = (v, path, errors) => {
  if (typeof v !== 'string' || !ASSET_ID.test(v)) errors.push({ path, message: 'must be an asset id, sha256- and 64 hex digits' });
};
const required =
  (...fields: string[]): Check =>
  (v, path, errors) => {
    if (isRecord(v)) for (const f of fields) if (v[f] === undefined) errors.push({ path: `${path}.${f}`, message: 'is required' });
  };
const pair =
  (item: Check): Check =>
  (v, path, errors) => {
    if (!Array.isArray(v) || v.length !== 2) errors.push({ path, message: 'must be a list of two' });
    else v.forEach((x, i) => item(x, `${path}[${i}]`, errors));
  };


/** Runs every check on the same value. */
const all =
  (...checks: Check[]): Check =>
  (v, path, errors) =>
    checks.forEach((check) => check(v, path, errors));

const texture = byType({
  checker: all(record(TEXTURE_FIELDS.checker, { type: () => {}, colors: pair(color), size: positiveNumber }), required('colors')),
  // an image names an uploaded asset (the editor's) or a file beside the scene (the command line's)
  image: all(record(TEXTURE_FIELDS.image, { type: () => {}, asset: assetId, file: string, scale: pair(positiveNumber) }), imageSource),
});
const type: Check = () => {};
const materialChecks = { type, color, diffuse: number, specular: number, shininess: number, reflectivity: number, ior: number, texture };
const material = byType(
  Object.fromEntries(Object.entries(MATERIAL_FIELDS).map(([k, f]) => [k, record(f, materialChecks)])),
);
const objectChecks = {
  type, center: vector, radius: number, size: vector, rotation: vector, point: vector, normal: vector, material,
  obj: string, file: string, asset: assetId, position: vector, scale: positive, name: string,
};
const object = byType({
  ...Object.fromEntries(Object.entries(OBJECT_FIELDS).map(([k, f]) => [k, record(f, objectChecks)])),
  mesh: all(record(OBJECT_FIELDS.mesh, objectChecks), meshSource),
  gltf: all(record(OBJECT_FIELDS.gltf, objectChecks), modelSource),
});
const lightChecks = { type, name: string, position: vector, color, intensity: number, falloff: boolean, radius: number, size: size2, lookAt: vector, twoSided: boolean };
const light = byType(Object.fromEntries(Object.entries(LIGHT_FIELDS).map(([k, f]) => [k, record(f, lightChecks)])));

const scene = record(SCENE_FIELDS, {
  version: integer,
  name: string,
  image: record(IMAGE_FIELDS, { width: integer, height: integer, format: oneOf('png', 'jpg'), quality: number }),
  camera: record(CAMERA_FIELDS, { position: vector, lookAt: vector, up: vector, fov: number }),
  background: color,
  ambient: number,
  render: record(RENDER_FIELDS, {
    sampler: oneOf('regular', 'random', 'jittered', 'multijittered', 'sobol'),
    samples: integer,
    maxDepth: integer,
    seed: integer,
    adaptive: number,
  }),
  lights: list(light),
  objects: list(object),
});

/** Checks a parsed JSON value; on success it is returned typed as a Scene. */
export function validateScene(value: unknown): ParseResult {
  const errors: ShapeError[] = [];
  scene(value, '', errors);
  if (isRecord(value)) {
    if (!('objects' in value)) errors.push({ path: 'objects', message: 'is required (a list of objects, possibly empty)' });
    if (typeof value.version === 'number' && value.version > FORMAT_VERSION) {
      errors.push({ path: 'version', message: `is newer than this editor understands (it reads version ${FORMAT_VERSION})` });
    }
  }
  return errors.length === 0 ? { ok: true, scene: value as Scene } : { ok: false, errors };
}

/** Parses JSON text and checks its shape; a syntax error is reported at the path ''. */
export function parseScene(text: string): ParseResult {
  let value: unknown;
  try {
    value = JSON.parse(text);
  } catch (error) {
    return { ok: false, errors: [{ path: '', message: `is not valid JSON: ${(error as Error).message}` }] };
  }
  return validateScene(value);
}

/** One line per problem, for messages: "objects[0].radius: must be a finite number". */
export function describeErrors(errors: ShapeError[], max = 5): string {
  const lines = errors.slice(0, max).map((e) => (e.path ? `${e.path}: ${e.message}` : e.message));
  if (errors.length > max) lines.push(`… and ${errors.length - max} more`);
  return lines.join('\n');
}
