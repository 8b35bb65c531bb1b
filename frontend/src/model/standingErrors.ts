/**
 * Which of the server's field errors still stand. The server judged one scene; the editor shows
 * its verdict on a field only while everything that rule read is unchanged, so a message goes as
 * soon as its field is edited (and the editor's own checks, `sceneRules.ts`, judge the new value).
 */
import type { Problem } from './schemaRules';
import type { Scene } from './types';
import { sameJson } from './sameJson';

/** Messages by scene JSON path (`objects[2].radius`, `camera.up`). */
export type FieldErrors = Record<string, string>;

/** The fields a rule reads beyond its own: the camera's rules and the render budget. */
const READS: Record<string, string[]> = {
  'camera.up': ['camera.position', 'camera.lookAt', 'camera.up'],
  'camera.lookAt': ['camera.position', 'camera.lookAt'],
  'render.samples': ['render.samples', 'render.sampler', 'image.width', 'image.height'],
  image: ['image', 'render.samples'],
};

/** What a rule on `path` reads: {@link READS}, an area light's aim with its position, else the field alone. */
function readsOf(path: string): string[] {
  const aim = /^(lights\[\d+\])\.lookAt$/.exec(path);
  return READS[path] ?? (aim ? [`${aim[1]}.position`, path] : [path]);
}

/** The steps of a JSON path: `objects[2].center[0]` → ['objects', 2, 'center', 0]. */
export function pathSteps(path: string): (string | number)[] {
  const steps: (string | number)[] = [];
  for (const m of path.matchAll(/([^.[\]]+)|\[(\d+)\]/g)) steps.push(m[2] !== undefined ? Number(m[2]) : m[1]);
  return steps;
}

/** The value at a JSON path, or undefined when any step is missing. */
export function valueAt(value: unknown, path: string): unknown {
  let at = value;
  for (const step of pathSteps(path)) {
    if (at === null || typeof at !== 'object') return undefined;
    at = (at as Record<string | number, unknown>)[step];
  }
  return at;
}

/** The errors of `judged` whose fields (and what their rule reads) are the same in `scene`. */
export function standingErrors(errors: FieldErrors, judged: Scene, scene: Scene): FieldErrors {
  const out: FieldErrors = {};
  for (const [path, message] of Object.entries(errors)) {
    const reads = readsOf(path);
    if (reads.every((p) => sameJson(valueAt(judged, p), valueAt(scene, p)))) out[path] = message;
  }
  return out;
}

/** One message per field: the editor's own problems first, then the server's that still stand. */
export function mergeErrors(problems: Problem[], ...server: FieldErrors[]): FieldErrors {
  const out: FieldErrors = {};
  for (const p of problems) if (!(p.path in out)) out[p.path] = p.message;
  for (const errors of server) for (const [path, message] of Object.entries(errors)) if (!(path in out)) out[path] = message;
  return out;
}
