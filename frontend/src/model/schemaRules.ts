/**
 * The value rules of the editor's copy of the scene schema (`scene.schema.json`, kept equal to the
 * server's by a server test), checked in the editor so a bad value is flagged as soon as it is in
 * the scene: a radius of -1 in an opened file, a width over the limit. Only the keywords the schema
 * uses on values are read (bounds, whole numbers, a zero `up`); shapes are `validate.ts`'s business.
 * Messages are the server's (Bean Validation's), so a field says the same thing before and after
 * a Render.
 */
import schema from './scene.schema.json';
import type { Scene } from './types';
import { isFiniteNumber as isNumber } from '../util/json';

/** One problem with the scene, named by its JSON path (`objects[2].radius`). */
export interface Problem {
  path: string;
  message: string;
}

type Rule = Record<string, unknown>;
const defs = (schema as { $defs: Record<string, Rule> }).$defs;

/** Follows `$ref`; a `oneOf` of kinds is resolved by the value's `type`. */
function resolve(rule: Rule | undefined, value: unknown): Rule | undefined {
  if (!rule) return undefined;
  if (typeof rule.$ref === 'string') return resolve(defs[rule.$ref.replace('#/$defs/', '')], value);
  if (Array.isArray(rule.oneOf) && rule.properties === undefined) {
    const type = (value as { type?: unknown } | null)?.type;
    const kind = (rule.oneOf as Rule[])
      .map((r) => resolve(r, value))
      .find((r) => ((r?.properties as Record<string, Rule> | undefined)?.type as Rule | undefined)?.const === type);
    return kind;
  }
  return rule;
}


/** A bound as the server's message writes it: `4096`, `0.5`, and from a million on `1e6`, `1e12`, `-1e12`. */
export function boundText(n: number): string {
  return Math.abs(n) >= 1e6 ? n.toExponential().replace('e+', 'e') : String(n);
}

function checkNumber(rule: Rule, value: number, path: string, out: Problem[]): void {
  if (rule.type === 'integer' && !Number.isInteger(value)) out.push({ path, message: 'must be a whole number' });
  if (isNumber(rule.exclusiveMinimum) && value <= rule.exclusiveMinimum) out.push({ path, message: `must be greater than ${boundText(rule.exclusiveMinimum)}` });
  if (isNumber(rule.minimum) && value < rule.minimum) out.push({ path, message: `must be greater than or equal to ${boundText(rule.minimum)}` });
  if (isNumber(rule.exclusiveMaximum) && value >= rule.exclusiveMaximum) out.push({ path, message: `must be less than ${boundText(rule.exclusiveMaximum)}` });
  if (isNumber(rule.maximum) && value > rule.maximum) out.push({ path, message: `must be less than or equal to ${boundText(rule.maximum)}` });
}

function walk(rule: Rule | undefined, value: unknown, path: string, out: Problem[]): void {
  const r = resolve(rule, value);
  if (!r || value === undefined || value === null) return;
  if (isNumber(value)) return checkNumber(r, value, path, out);
  if (Array.isArray(value)) {
    // `not: {items: {const: 0}}` is the schema's way of saying "not the zero vector" (NonZeroVector).
    if (r.not && value.length > 0 && value.every((v) => v === 0)) out.push({ path, message: 'must not be a zero-length vector' });
    value.forEach((item, i) => walk(r.items as Rule | undefined, item, `${path}[${i}]`, out));
    return;
  }
  if (typeof value === 'object' && r.properties) {
    const properties = r.properties as Record<string, Rule>;
    for (const [key, v] of Object.entries(value as Record<string, unknown>)) {
      walk(properties[key], v, path ? `${path}.${key}` : key, out);
    }
  }
}

/** Every value of the scene that breaks a rule of the schema, in document order. */
export function schemaProblems(scene: Scene): Problem[] {
  const out: Problem[] = [];
  walk(schema as Rule, scene, '', out);
  return out;
}
