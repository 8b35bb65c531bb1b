/** What the user has picked in the views, the outline or the inspector. */
export type Selection =
  | { kind: 'object'; index: number }
  | { kind: 'light'; index: number }
  /** An area light's aim (its `lookAt`), moved in the plan views as the camera's target is. */
  | { kind: 'lightAim'; index: number }
  | { kind: 'camera' }
  | { kind: 'target' }
  | null;

/** Something that can be dragged: any selection but none. */
export type DragTarget = Exclude<Selection, null>;

/** What a multi-selection holds: objects and lights (the camera and its target are picked alone). */
export type SceneItem = { kind: 'object'; index: number } | { kind: 'light'; index: number };

/** True when both name the same thing. */
export function sameSelection(a: Selection, b: Selection): boolean {
  if (a === null || b === null) return a === b;
  if (a.kind !== b.kind) return false;
  return !('index' in a) || a.index === (b as { index: number }).index;
}

/** True for an object or a light: what can join a multi-selection. */
export function isSceneItem(selection: Selection): selection is SceneItem {
  return selection?.kind === 'object' || selection?.kind === 'light';
}

/** True when `selection` is one of `items`. */
export function inItems(items: readonly SceneItem[], selection: Selection): boolean {
  return items.some((item) => sameSelection(item, selection));
}

/** What is selected after a plain click (or a pick from the list): that alone. */
export function selectOne(selection: Selection): { primary: Selection; items: SceneItem[] } {
  return { primary: selection, items: isSceneItem(selection) ? [selection] : [] };
}

/**
 * What is selected after a Shift or Ctrl click on `clicked`: an object or light joins the
 * selection and becomes its primary (what the inspector and the 3D handles show), or leaves it if
 * it was in it (the last one left becomes the primary); the camera or its target is picked alone.
 */
export function toggleItem(items: readonly SceneItem[], primary: Selection, clicked: Selection): { primary: Selection; items: SceneItem[] } {
  if (!isSceneItem(clicked)) return selectOne(clicked);
  const kept = isSceneItem(primary) ? items.filter(isSceneItem) : [];
  if (inItems(kept, clicked)) {
    const left = kept.filter((item) => !sameSelection(item, clicked));
    return { primary: left.length > 0 ? left[left.length - 1] : null, items: left };
  }
  return { primary: clicked, items: [...kept, clicked] };
}

/** What is selected after a box select: `found`, added to the selection with `add` (Shift), else alone. */
export function selectFound(items: readonly SceneItem[], primary: Selection, found: readonly SceneItem[], add: boolean): { primary: Selection; items: SceneItem[] } {
  const base = add && isSceneItem(primary) ? [...items] : [];
  for (const item of found) if (!inItems(base, item)) base.push(item);
  if (base.length === 0) return { primary: add ? primary : null, items: [] };
  const newest = found.length > 0 ? found[found.length - 1] : base[base.length - 1];
  return { primary: add && found.length === 0 ? primary : newest, items: base };
}

/** A short human name: "Object 3", "Light 1", "Light 1 aim", "Camera", "Camera target". */
export function selectionLabel(selection: Selection): string {
  if (selection === null) return 'Nothing';
  switch (selection.kind) {
    case 'object':
      return `Object ${selection.index + 1}`;
    case 'light':
      return `Light ${selection.index + 1}`;
    case 'lightAim':
      return `Light ${selection.index + 1} aim`;
    case 'camera':
      return 'Camera';
    case 'target':
      return 'Camera target';
  }
}
