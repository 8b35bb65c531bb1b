/**
 * The rules the scene schema cannot state, checked in the editor with the server's own messages
 * (`SceneMapper`): the camera's (its target apart from it, `up` not along the view), the render
 * budget, and the sphere and area lights' ({@link lightProblems}). With {@link schemaProblems} they
 * let the editor flag a scene the server would refuse before Render is pressed; the server stays
 * the judge.
 */
import { resolveLight, resolveScene, sceneLights } from './defaults';
import { schemaProblems, type Problem } from './schemaRules';
import type { ResolvedLightOf, Scene } from './types';
import { cross, length, normalize, sub } from './vec';

/**
 * The server's default render budget (`studio.limits.max-pixel-samples`): width x height x
 * samples of one render. A server configured otherwise still has the last word.
 */
export const RENDER_BUDGET_SAMPLES = 268_435_456;

/** The camera's rules, as the server words them. */
export function cameraProblems(scene: Scene): Problem[] {
  const { position, lookAt, up } = resolveScene({ ...scene, objects: [] }).camera;
  if (position.every((p, i) => p === lookAt[i])) return [{ path: 'camera.lookAt', message: 'must differ from camera.position' }];
  const upLength = length(up);
  if (upLength === 0) return []; // the schema's rule says so
  if (length(cross(up, normalize(sub(lookAt, position)))) <= 1e-9 * upLength) {
    return [{ path: 'camera.up', message: "is parallel to the view direction (lookAt - position); the camera's roll is undefined" }];
  }
  return [];
}

/** Width x height x samples over the budget (only when each is within its own limit, as the server). */
export function budgetProblems(scene: Scene, budget = RENDER_BUDGET_SAMPLES): Problem[] {
  const { image, render } = resolveScene({ ...scene, objects: [] });
  const total = image.width * image.height * render.samples;
  if (total <= budget || image.width > 4096 || image.height > 4096 || render.samples > 1024) return [];
  const n = (x: number) => x.toLocaleString('en-US');
  return [{
    path: 'render.samples',
    message: `${image.width} x ${image.height} pixels x ${render.samples} samples = ${n(total)} samples, more than this server's render budget of ${n(budget)} samples per render; lower render.samples or the image size`,
  }];
}

/**
 * The sphere and area lights' rules, with Bean Validation's words as the schema's rules
 * have them: a point light's radius finite and at least 0, an area light's width and height greater
 * than 0 and its `lookAt` apart from its position (worded as the camera's). The radius and sizes
 * move to the schema's rules when the server publishes them ({@link sceneProblems} then keeps one
 * message per field).
 */
export function lightProblems(scene: Scene): Problem[] {
  const out: Problem[] = [];
  const finite = (v: unknown): v is number => typeof v === 'number' && Number.isFinite(v);
  sceneLights(scene).forEach((light, i) => {
    const path = `lights[${i}]`;
    if (light.type === 'point' && light.radius !== undefined) {
      if (!finite(light.radius)) out.push({ path: `${path}.radius`, message: 'must be a finite number' });
      else if (light.radius < 0) out.push({ path: `${path}.radius`, message: 'must be greater than or equal to 0' });
    }
    if (light.type !== 'area') return;
    light.size?.forEach((s, k) => {
      if (!finite(s)) out.push({ path: `${path}.size[${k}]`, message: 'must be a finite number' });
      else if (s <= 0) out.push({ path: `${path}.size[${k}]`, message: 'must be greater than 0' });
    });
    const { position, lookAt } = resolveLight(light) as ResolvedLightOf<'area'>;
    if (position.every((p, k) => p === lookAt[k])) out.push({ path: `${path}.lookAt`, message: `must differ from ${path}.position` });
  });
  return out;
}

/** Every problem the editor can see in a scene: the schema's value rules, then the camera's, the budget and the lights'. */
export function sceneProblems(scene: Scene): Problem[] {
  const problems = schemaProblems(scene);
  const named = new Set(problems.map((p) => p.path));
  const more = [...cameraProblems(scene), ...budgetProblems(scene), ...lightProblems(scene)].filter((p) => !named.has(p.path));
  return [...problems, ...more];
}
