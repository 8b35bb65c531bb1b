/** What the user has picked in the views, the outline or the inspector. */
export type Selection =
  | { kind: 'object'; index: number }
  | { kind: 'light'; index: number }
  | { kind: 'camera' }
  | { kind: 'target' }
  | null;

/** Something that can be dragged: any selection but none. */
export type DragTarget = Exclude<Selection, null>;

/** True when both name the same thing. */
export function sameSelection(a: Selection, b: Selection): boolean {
  if (a === null || b === null) return a === b;
  if (a.kind !== b.kind) return false;
  return !('index' in a) || a.index === (b as { index: number }).index;
}

/** A short human name: "Object 3", "Light 1", "Camera", "Camera target". */
export function selectionLabel(selection: Selection): string {
  if (selection === null) return 'Nothing';
  switch (selection.kind) {
    case 'object':
      return `Object ${selection.index + 1}`;
    case 'light':
      return `Light ${selection.index + 1}`;
    case 'camera':
      return 'Camera';
    case 'target':
      return 'Camera target';
  }
}
