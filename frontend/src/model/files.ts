/** Scene files: the download name of a scene and its text. */
import { formatScene } from './formatScene';
import type { Scene } from './types';

/** `${name}.json`, with path separators, quotes and control characters taken out. */
export function sceneFileName(scene: Scene): string {
  const base = (scene.name ?? 'render')
    // eslint-disable-next-line no-control-regex -- control characters are what this takes out
    .replace(/[\u0000-\u001f\u007f"'`<>:|?*]/g, '')
    .split(/[\\/]/)
    .filter((part) => part !== '' && part !== '.' && part !== '..')
    .join('-')
    .trim();
  return `${base || 'render'}.json`;
}

/** The text a saved scene file holds (vectors on one line, as `scenes/` are written). */
export function sceneFileText(scene: Scene): string {
  return formatScene(scene) + '\n';
}
