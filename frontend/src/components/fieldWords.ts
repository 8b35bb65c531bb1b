/**
 * Field paths in the inspector's words: `objects[0].radius` is `Sphere 1 › Radius`,
 * `camera.up` is `Camera › Up`. Problems are shown this way (the path stays in a tooltip), and the
 * server's messages lose what only an operator knows (configuration keys).
 */
import { pathSteps } from '../model/standingErrors';
import type { Scene } from '../model/types';
import { sceneLights } from '../model/defaults';
import { lightLabel, objectLabel } from './labels';
import { OVERRIDE_FIELDS } from './labels';

const AXES = ['x', 'y', 'z'];
const SIZE_AXES = ['w', 'h'];

/** The inspector's label of a field of each part of the scene. */
const FIELD_WORDS: Record<string, Record<string, string>> = {
  object: {
    center: 'Center', radius: 'Radius', size: 'Size', rotation: 'Rotation', point: 'Point', normal: 'Normal',
    position: 'Position', scale: 'Scale', obj: 'OBJ', file: 'File', name: 'Name', type: 'Type', material: 'Material',
  },
  material: { type: 'Material type', color: 'Color', ...Object.fromEntries(Object.entries(OVERRIDE_FIELDS).map(([k, v]) => [k, v.label])) },
  light: {
    position: 'Position', color: 'Color', intensity: 'Intensity', falloff: 'Falls off with distance', name: 'Name', radius: 'Radius',
    size: 'Size', lookAt: 'Aim', twoSided: 'Two-sided',
  },
  camera: { position: 'Position', lookAt: 'Look at', up: 'Up', fov: 'Field of view' },
  image: { width: 'Width', height: 'Height', format: 'Format', quality: 'JPEG quality' },
  render: { sampler: 'Sampler', samples: 'Samples per pixel', maxDepth: 'Max depth', seed: 'Seed', adaptive: 'Adaptive threshold' },
  scene: { name: 'Name', background: 'Background', ambient: 'Ambient', version: 'Version', lights: 'Lights', objects: 'Objects' },
};

/** The words of the steps after a part: `['material', 'color']` → `Material › Color`, `['center', 0]` → `Center x`. */
function stepWords(part: string, steps: (string | number)[]): string[] {
  const words: string[] = [];
  let table = FIELD_WORDS[part];
  let axes = AXES;
  for (const step of steps) {
    if (typeof step === 'number') {
      if (words.length > 0) words[words.length - 1] += ` ${axes[step] ?? step + 1}`;
      continue;
    }
    // an area light's size is [width, height], as its inspector tags them
    axes = part === 'light' && step === 'size' ? SIZE_AXES : AXES;
    words.push(table?.[step] ?? step);
    table = step === 'material' ? FIELD_WORDS.material : {};
  }
  return words;
}

/** Where a path points, as the inspector names it: `Sphere "ball" › Radius`, `Render › Samples per pixel`. */
export function describeField(scene: Scene, path: string): string {
  const steps = pathSteps(path);
  const [head, index] = steps;
  let words: string[];
  if (head === 'objects' && typeof index === 'number') {
    words = [objectLabel(scene, index), ...stepWords('object', steps.slice(2))];
  } else if (head === 'lights' && typeof index === 'number') {
    words = [lightLabel(sceneLights(scene), index), ...stepWords('light', steps.slice(2))];
  } else if (head === 'camera' || head === 'image' || head === 'render') {
    words = [String(head[0]).toUpperCase() + String(head).slice(1), ...stepWords(String(head), steps.slice(1))];
  } else if (path === '') {
    words = ['Scene'];
  } else {
    words = ['Scene', ...stepWords('scene', steps)];
  }
  return words.join(' › ');
}

/**
 * A server message in the editor's words: configuration keys go (they mean something to whoever
 * runs the server, not to the user), JSON paths in the text become field names.
 */
export function plainMessage(scene: Scene, message: string): string {
  return message
    .replace(/\s*\((?:studio|spring|server)\.[\w.-]+\)/g, '')
    .replace(/\b(?:studio|spring)\.[a-z][\w-]*(?:\.[\w-]+)+/g, 'a server setting')
    .replace(/\b(?:(?:camera|image|render)|(?:lights|objects)\[\d+\])\.[a-zA-Z]+\b/g, (p) => describeField(scene, p))
    .replace(/\(lookAt - position\)/g, '(Look at − Position)');
}
