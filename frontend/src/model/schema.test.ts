/**
 * The editor's types against the JSON Schema the server publishes
 * (`src/model/scene.schema.json`, draft 2020-12), so the two ends cannot drift apart.
 * Skipped, with a note, while the server has not generated the file yet.
 */
import Ajv2020 from 'ajv/dist/2020';
import { existsSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { useSceneStore } from '../store/sceneStore';
import { exampleScenes } from '../test/scenes';
import { blankScene, MATERIAL_DEFAULTS, newLight, newObject } from './defaults';
import {
  CAMERA_FIELDS,
  IMAGE_FIELDS,
  LIGHT_FIELDS,
  MATERIAL_FIELDS,
  OBJECT_FIELDS,
  ADDABLE_TYPES,
  RENDER_FIELDS,
  SCENE_FIELDS,
  type Scene,
} from './types';
import { validateScene } from './validate';

type JsonSchema = {
  $ref?: string;
  $defs?: Record<string, JsonSchema>;
  properties?: Record<string, JsonSchema>;
  required?: string[];
  const?: unknown;
  oneOf?: JsonSchema[];
  anyOf?: JsonSchema[];
  allOf?: JsonSchema[];
  [key: string]: unknown;
};

const SCHEMA_PATH = resolve(process.cwd(), 'src/model/scene.schema.json');
const schema: JsonSchema | null = existsSync(SCHEMA_PATH) ? (JSON.parse(readFileSync(SCHEMA_PATH, 'utf8')) as JsonSchema) : null;

/** Follows `#/$defs/Name` references within the schema. */
function deref(node: JsonSchema): JsonSchema {
  if (!node.$ref) return node;
  const name = node.$ref.replace(/^#\/\$defs\//, '');
  const target = schema?.$defs?.[name];
  if (!target) throw new Error(`unresolved $ref ${node.$ref}`);
  return deref(target);
}

/** The sub-schema that has `properties`: the node itself, or one inside anyOf/oneOf/allOf (e.g. nullable). */
function withProperties(node: JsonSchema): JsonSchema {
  const n = deref(node);
  if (n.properties) return n;
  for (const alt of [...(n.anyOf ?? []), ...(n.oneOf ?? []), ...(n.allOf ?? [])]) {
    const found = alt.$ref || alt.properties || alt.anyOf || alt.oneOf ? withProperties(alt) : null;
    if (found?.properties) return found;
  }
  throw new Error('no properties in ' + JSON.stringify(node));
}

/** `{kind: [field names]}` of a polymorphic def (`Object`, `Material`, `Light`). */
function kindsOf(defName: string): Record<string, string[]> {
  const union = schema?.$defs?.[defName];
  expect(union?.oneOf, `$defs.${defName}.oneOf`).toBeDefined();
  return Object.fromEntries(
    union!.oneOf!.map((ref) => {
      const def = deref(ref);
      return [String(def.properties?.type?.const), Object.keys(def.properties ?? {}).sort()];
    }),
  );
}

const sorted = (o: Record<string, readonly string[]>) =>
  Object.fromEntries(Object.entries(o).map(([k, v]) => [k, [...v].sort()]));

describe.skipIf(schema === null)('the editor types follow the server JSON Schema (scene.schema.json)', () => {
  it('has the same object, material and light kinds, each with the same field names', () => {
    expect(kindsOf('Object')).toEqual(sorted(OBJECT_FIELDS));
    expect(kindsOf('Material')).toEqual(sorted(MATERIAL_FIELDS));
    expect(kindsOf('Light')).toEqual(sorted(LIGHT_FIELDS));
  });

  it('has the same scene, image, camera and render fields, and requires objects', () => {
    const root = schema!;
    expect(Object.keys(root.properties ?? {}).sort()).toEqual([...SCENE_FIELDS].sort());
    expect(root.required).toContain('objects');
    expect(root.additionalProperties).toBe(false);
    const fieldsOf = (name: string) => Object.keys(withProperties(root.properties![name]).properties!).sort();
    expect(fieldsOf('image')).toEqual([...IMAGE_FIELDS].sort());
    expect(fieldsOf('camera')).toEqual([...CAMERA_FIELDS].sort());
    expect(fieldsOf('render')).toEqual([...RENDER_FIELDS].sort());
  });

  const ajv = new Ajv2020({ allErrors: true, strict: false });
  const validate = schema ? ajv.compile(schema) : () => true;

  it.each(exampleScenes())('accepts the example %s, which also loads into the store', (_file, json) => {
    const ok = validate(json);
    expect(ok ? [] : (validate as { errors?: unknown }).errors).toEqual([]);
    expect(validateScene(json).ok).toBe(true);
    useSceneStore.getState().loadScene(json as Scene);
    expect(useSceneStore.getState().scene).toEqual(json);
  });

  it('accepts what the editor writes: new objects, lights, every material kind, a blank scene', () => {
    const scene: Scene = {
      ...blankScene(),
      lights: [newLight()],
      objects: [
        ...ADDABLE_TYPES.map(newObject),
        ...Object.values(MATERIAL_DEFAULTS).map((material) => ({ type: 'sphere' as const, material })),
      ],
    };
    const ok = validate(scene);
    expect(ok ? [] : (validate as { errors?: unknown }).errors).toEqual([]);
    expect(validate(blankScene())).toBe(true);
  });

  it('refuses an override that belongs to another material kind', () => {
    expect(validate({ objects: [{ type: 'sphere', material: { type: 'mirror', ior: 1.5 } }] })).toBe(false);
  });
});

describe('the example scenes without a schema', () => {
  it.each(exampleScenes())('%s has the shape the editor checks and loads into the store', (_file, json) => {
    const result = validateScene(json);
    expect(result.ok ? [] : result.errors).toEqual([]);
    useSceneStore.getState().loadScene(json as Scene);
    expect(useSceneStore.getState().scene).toEqual(json);
  });
});
