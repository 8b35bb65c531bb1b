/**
 * Edits of a multi-selection (objects and lights together): move, delete and duplicate them all in
 * one scene change, which the store makes one undo step. Pure, like the single edits in edits.ts.
 */
import { copyName, withName } from './naming';
import { sceneLights } from './defaults';
import { copyAside, lightAside, nudgeTarget } from './edits';
import type { SceneItem } from './selection';
import type { Scene, Vec3 } from './types';

/** Moves every item by the same offset. */
export function nudgeItems(scene: Scene, items: readonly SceneItem[], by: Vec3): Scene {
  return items.reduce((next, item) => nudgeTarget(next, item, by), scene);
}

/** Removes every item; the others keep their order. */
export function removeItems(scene: Scene, items: readonly SceneItem[]): Scene {
  const objects = indices(items, 'object');
  const lights = indices(items, 'light');
  const next: Scene = { ...scene, objects: scene.objects.filter((_, i) => !objects.has(i)) };
  if (lights.size > 0) next.lights = sceneLights(scene).filter((_, i) => !lights.has(i));
  return next;
}

/**
 * Adds a copy of every item, moved aside as a single duplicate is, after the scene's objects and
 * lights in the items' order; returns the scene and the copies (to select them).
 */
export function duplicateItems(scene: Scene, items: readonly SceneItem[]): { scene: Scene; copies: SceneItem[] } {
  const lights = sceneLights(scene);
  const objectCopies = [...indices(items, 'object')].filter((i) => scene.objects[i]).map((i) => copyAside(scene.objects[i]));
  const lightCopies = [...indices(items, 'light')].filter((i) => lights[i]).map((i) => lightAside(lights[i]));
  const next: Scene = { ...scene, objects: [...scene.objects] };
  // each copy named apart from the scene and from the copies before it
  for (const copy of objectCopies) next.objects.push(withName(copy, copyName(next, copy.name, copy.type)));
  for (const copy of lightCopies) next.lights = [...sceneLights(next), withName(copy, copyName(next, copy.name, copy.type))];
  const copies: SceneItem[] = [
    ...objectCopies.map((_, k) => ({ kind: 'object' as const, index: scene.objects.length + k })),
    ...lightCopies.map((_, k) => ({ kind: 'light' as const, index: lights.length + k })),
  ];
  return { scene: next, copies };
}

/** The indices of one kind among the items, in the items' order, each once. */
function indices(items: readonly SceneItem[], kind: SceneItem['kind']): Set<number> {
  return new Set(items.filter((item) => item.kind === kind).map((item) => item.index));
}
