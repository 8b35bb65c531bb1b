/**
 * Checks that an unknown JSON value has the shape of a scene before the editor loads it:
 * known fields only, `type` of every polymorphic element known, vectors of three finite
 * numbers, colours `#rrggbb`, numbers as numbers. Value ranges are the server's business, but
 * for a mesh, whose triangles the editor reads itself: exactly one of `obj` and `file`, and a
 * `scale` greater than 0 (as the server's rules).
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

const positive: Check = (v, path, errors) => {
  if (typeof v !== 'number' || !Number.isFinite(v) || v <= 0) errors.push({ path, message: 'must be a finite number greater than 0' });
};

/** A mesh names its triangles by exactly one of `obj` and `file` (the message goes on the object, as the server's). */
const meshSource: Check = (v, path, errors) => {
  if (!isRecord(v)) return;
  const hasObj = v.obj !== undefined;
  if (hasObj === (v.file !== undefined)) {
    errors.push({ path, message: hasObj ? 'give the mesh either "obj" or "file", not both' : 'a mesh needs its OBJ text in "obj" or a "file" name' });
  }
};

/** Runs every check on the same value. */
const all =
  (...checks: Check[]): Check =>
  (v, path, errors) =>
    checks.forEach((check) => check(v, path, errors));

const type: Check = () => {};
const texture = byType({
  checker: record(TEXTURE_FIELDS.checker, { type, colors: list(color), size: positive }),
  image: record(TEXTURE_FIELDS.image, { type, asset: string, file: string, scale: list(positive) }),
});
const materialChecks = {
  type, color, diffuse: number, specular: number, shininess: number, reflectivity: number, ior: number, texture,
};
const material = byType(
  Object.fromEntries(Object.entries(MATERIAL_FIELDS).map(([k, f]) => [k, record(f, materialChecks)])),
);
const objectChecks = {
  type, center: vector, radius: number, size: vector, rotation: vector, point: vector, normal: vector, material,
  obj: string, file: string, position: vector, scale: positive, name: string,
};
const object = byType({
  ...Object.fromEntries(Object.entries(OBJECT_FIELDS).map(([k, f]) => [k, record(f, objectChecks)])),
  mesh: all(record(OBJECT_FIELDS.mesh, objectChecks), meshSource),
});
const light = byType({ point: record(LIGHT_FIELDS.point, { type, name: string, position: vector, color, intensity: number, falloff: boolean }) });

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
