/**
 * Names of new things: every object and light the editor adds gets a name no other object or light
 * of the scene has, so the inspector's Name field is never empty and the outline tells them apart
 * (the three.js editor and Blender name new things the same way). Pure.
 */
import { sceneLights } from './defaults';
import type { Scene } from './types';

/** What a new object of each kind is called before its number (as the outline calls its kind). */
export const KIND_NAMES = { sphere: 'Sphere', box: 'Box', plane: 'Plane', mesh: 'Mesh', gltf: 'glTF model' } as const;

/** The names the scene's objects and lights already carry. */
function namesIn(scene: Scene): Set<string> {
  const names = new Set<string>();
  for (const item of [...scene.objects, ...sceneLights(scene)]) {
    if ('name' in item && typeof item.name === 'string') names.add(item.name);
  }
  return names;
}

/**
 * `base` followed by a number no object or light of the scene is named with, counting on from the
 * things already there (`Sphere 3` beside two others; as the outline numbers unnamed ones, so the
 * default light, "Light 1", is followed by `Light 2`); with `numbered` false, `base` itself when it
 * is free (an imported file's name: `teapot`, then `teapot 2`).
 */
export function uniqueName(scene: Scene, base: string, numbered = true, already = 0): string {
  const taken = namesIn(scene);
  const stem = base.trim() || 'Object';
  if (!numbered && !taken.has(stem)) return stem;
  for (let n = numbered ? already + 1 : 2; ; n++) {
    const name = `${stem} ${n}`;
    if (!taken.has(name)) return name;
  }
}

/**
 * A copy's name (Duplicate, a multi-selection's duplicate): the original's stem with a number no
 * other object or light of `scene` has (`Sphere 3` copied beside four objects: `Sphere 5`; `ball`:
 * `ball 2`); none when the original has none.
 */
export function copyName(scene: Scene, name: string | undefined, kind: keyof typeof KIND_NAMES | 'point' | 'area'): string | undefined {
  if (!name) return undefined;
  const stem = name.replace(/ \d+$/, '');
  const kindName = kind === 'point' ? 'Light' : kind === 'area' ? 'Area light' : KIND_NAMES[kind];
  if (stem === kindName) return uniqueName(scene, stem, true, kind === 'point' || kind === 'area' ? sceneLights(scene).length : scene.objects.length);
  return uniqueName(scene, stem, false);
}

/** `item` with `name`, or as it is when there is none (no `name: undefined` in the file). */
export function withName<T extends object>(item: T, name: string | undefined): T {
  return name === undefined ? item : { ...item, name };
}
