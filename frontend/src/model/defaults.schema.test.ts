/**
 * The editor's defaults against the ones the server publishes in its JSON Schema ("default" keys
 * in `scene.schema.json`, from the server's SceneDefaults and the engine's MaterialDefaults): every
 * published default is the editor's, and every default the editor fills in is published (but
 * render.adaptive, whose default depends on the sampler).
 */
import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';
import { AREA_LIGHT_DEFAULTS, LIGHT_DEFAULTS, MATERIAL_DEFAULTS, OBJECT_DEFAULTS, SCENE_DEFAULTS } from './defaults';

type Schema = { properties?: Record<string, { default?: unknown }>; $defs?: Record<string, Schema> };
const schema = JSON.parse(readFileSync(resolve(process.cwd(), 'src/model/scene.schema.json'), 'utf8')) as Schema;

/** The published defaults of one record of the schema, field by field. */
function published(record: Schema | undefined): Record<string, unknown> {
  return Object.fromEntries(
    Object.entries(record?.properties ?? {}).flatMap(([field, s]) => (s.default === undefined ? [] : [[field, s.default]])),
  );
}

const capitalise = (s: string) => s.charAt(0).toUpperCase() + s.slice(1);
const defs = schema.$defs ?? {};

/** A light kind's defaults but its type. */
function lightDefaults(defaults: object): Record<string, unknown> {
  return Object.fromEntries(Object.entries(defaults).filter(([field]) => field !== 'type'));
}

/** Each record of the schema with the editor's defaults for it; fields without a default are left out. */
const RECORDS: [string, Schema | undefined, Record<string, unknown>][] = [
  ['the scene', schema, { version: SCENE_DEFAULTS.version, name: SCENE_DEFAULTS.name, background: SCENE_DEFAULTS.background, ambient: SCENE_DEFAULTS.ambient }],
  ['image', defs.Image, { ...SCENE_DEFAULTS.image }],
  ['camera', defs.Camera, { ...SCENE_DEFAULTS.camera }],
  ['render', defs.Render, Object.fromEntries(Object.entries(SCENE_DEFAULTS.render).filter(([field]) => field !== 'adaptive'))],
  ['a light', defs.PointLight, lightDefaults(LIGHT_DEFAULTS)],
  ['an area light', defs.AreaLight, lightDefaults(AREA_LIGHT_DEFAULTS)],
  ...Object.entries(OBJECT_DEFAULTS).map(([type, d]): [string, Schema | undefined, Record<string, unknown>] => [
    `a ${type}`, defs[`${capitalise(type)}Object`], Object.fromEntries(Object.entries(d).filter(([field]) => field !== 'type')),
  ]),
  ...Object.entries(MATERIAL_DEFAULTS).map(([type, d]): [string, Schema | undefined, Record<string, unknown>] => [
    `${type} material`, defs[`${capitalise(type)}Material`], Object.fromEntries(Object.entries(d).filter(([field]) => field !== 'type')),
  ]),
];

describe('the editor fills in the defaults the server publishes', () => {
  it.each(RECORDS)('%s', (_, record, editor) => {
    expect(record, 'the record is in the schema').toBeDefined();
    expect(published(record)).toEqual(editor);
  });

  it('publishes no default for render.adaptive, which depends on the sampler', () => {
    expect(defs.Render?.properties?.adaptive?.default).toBeUndefined();
  });
});
