/**
 * Stable ids of objects and lights, for the editor only: `object-2`, `light-1`. Scenes are
 * immutable, so an id is kept beside each object value (a WeakMap, so JSON, files and the server
 * never see it) and carried from one version of a scene to the next by {@link carryIds}: an
 * object kept as it was keeps its id, an object edited in place inherits the id of the one it
 * replaced, anything else (added, duplicated, pasted, loaded) gets a new number. Undo brings back
 * the very objects, with their ids. Labels are made from ids, so deleting Box 1 leaves Sphere 2
 * named Sphere 2.
 */
import { LIGHT_TYPES, type Light, type Scene, type SceneObject } from './types';

type Item = SceneObject | Light;
const ids = new WeakMap<object, string>();

/** The editor's id of an object or light, once a scene holding it has passed {@link carryIds}. */
export function idOf(item: Item | undefined): string | undefined {
  return item ? ids.get(item) : undefined;
}

/** The number in an id (`object-12` → 12), or undefined. */
export function idNumber(id: string | undefined): number | undefined {
  const m = id ? /-(\d+)$/.exec(id) : null;
  return m ? Number(m[1]) : undefined;
}

/** Objects are numbered together (a scene opens with the labels of its order: Box 1, Sphere 2), lights apart. */
const kindOf = (item: Item) => ((LIGHT_TYPES as readonly string[]).includes(item.type) ? 'light' : 'object');

function carry(previous: Item[], next: Item[]): void {
  const kept = new Set<Item>(next);
  const top = new Map<string, number>();
  for (const item of [...previous, ...next]) {
    const n = idNumber(ids.get(item));
    if (n !== undefined) top.set(kindOf(item), Math.max(top.get(kindOf(item)) ?? 0, n));
  }
  next.forEach((item, i) => {
    if (ids.has(item)) return;
    const replaced = previous[i];
    const inherited = replaced && !kept.has(replaced) && replaced.type === item.type ? ids.get(replaced) : undefined;
    if (inherited && !next.some((other) => other !== item && ids.get(other) === inherited)) {
      ids.set(item, inherited);
      return;
    }
    const n = (top.get(kindOf(item)) ?? 0) + 1;
    top.set(kindOf(item), n);
    ids.set(item, `${kindOf(item)}-${n}`);
  });
}

/** Gives every object and light of `next` its id, carried over from `previous` where it continues one; returns `next`. */
export function carryIds(previous: Scene | null, next: Scene): Scene {
  carry(previous?.objects ?? [], next.objects);
  if (next.lights) carry(previous?.lights ?? [], next.lights);
  return next;
}
