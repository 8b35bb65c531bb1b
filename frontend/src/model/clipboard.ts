/**
 * Copy and paste as scene JSON: what is copied is a scene file of its own holding the selected
 * object or light (so it pastes into another tab, or into a text editor and back, and a whole
 * scene file pastes too); pasting adds every object and light of such a scene. Pure.
 */
import { FORMAT_VERSION, resolveObject, sceneLights } from './defaults';
import { anchorField, DUPLICATE_OFFSET, lightAside } from './edits';
import { objectAnchor } from './projection';
import type { SceneItem, Selection } from './selection';
import type { Light, Scene, SceneObject, Vec3 } from './types';
import { parseScene } from './validate';
import { add, vecEquals } from './vec';

/**
 * The selection as the text of a scene file, or null when nothing copyable is selected: every
 * selected object and light when several are (`items`), else the one selected.
 */
export function copyText(scene: Scene, selection: Selection, items: readonly SceneItem[] = []): string | null {
  if (items.length > 1) {
    const lights = sceneLights(scene);
    const objects = items.flatMap((i) => (i.kind === 'object' && scene.objects[i.index] ? [scene.objects[i.index]] : []));
    const picked = items.flatMap((i) => (i.kind === 'light' && lights[i.index] ? [lights[i.index]] : []));
    if (objects.length + picked.length > 0) {
      return JSON.stringify({ version: FORMAT_VERSION, ...(picked.length > 0 ? { lights: picked } : {}), objects }, null, 2);
    }
  }
  if (selection?.kind === 'object' && scene.objects[selection.index]) {
    return JSON.stringify({ version: FORMAT_VERSION, objects: [scene.objects[selection.index]] }, null, 2);
  }
  const light = selection?.kind === 'light' || selection?.kind === 'lightAim' ? sceneLights(scene)[selection.index] : undefined;
  if (light) return JSON.stringify({ version: FORMAT_VERSION, lights: [light], objects: [] }, null, 2);
  return null;
}

/** What a paste adds: the scene with the pasted things, and them to select (the first as primary). */
export interface Pasted {
  scene: Scene;
  selection: Selection;
  items: SceneItem[];
}

/**
 * Adds the objects and lights of pasted scene text; null when the text is no scene (the paste is
 * then left to whoever else wants it). A pasted object that would land exactly on one already
 * there (a copy pasted into its own scene) moves aside as a duplicate does.
 */
export function pasteText(scene: Scene, text: string): Pasted | null {
  const trimmed = text.trim();
  if (!trimmed.startsWith('{')) return null;
  const parsed = parseScene(trimmed);
  if (!parsed.ok) return null;
  const lightsIn = parsed.scene.lights ?? [];
  if (parsed.scene.objects.length === 0 && lightsIn.length === 0) return null;
  const taken = scene.objects.map((o) => objectAnchor(resolveObject(o)));
  const objects = parsed.scene.objects.map((o) => aside(o, taken));
  const lights = sceneLights(scene);
  const next: Scene = { ...scene, objects: [...scene.objects, ...objects] };
  // a light pasted onto one already there moves aside as a duplicate does (an area light with its aim)
  const onAnother = (l: Light) => l.position !== undefined && lights.some((m) => m.position && vecEquals(m.position, l.position!));
  if (lightsIn.length > 0) next.lights = [...lights, ...lightsIn.map((l) => (onAnother(l) ? lightAside(l) : l))];
  const selection: Selection = objects.length > 0 ? { kind: 'object', index: scene.objects.length } : { kind: 'light', index: lights.length };
  const items: SceneItem[] = [
    ...objects.map((_, k) => ({ kind: 'object' as const, index: scene.objects.length + k })),
    ...lightsIn.map((_, k) => ({ kind: 'light' as const, index: lights.length + k })),
  ];
  return { scene: next, selection, items };
}

function aside(object: SceneObject, taken: Vec3[]): SceneObject {
  if (object.type === 'plane') return object;
  let at = objectAnchor(resolveObject(object));
  while (taken.some((t) => vecEquals(t, at))) at = add(at, DUPLICATE_OFFSET);
  taken.push(at);
  return { ...object, [anchorField(object.type)]: at } as SceneObject;
}
