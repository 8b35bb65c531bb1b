/**
 * The one store of the editor: the scene with its undo history, the selection, a transient
 * drag preview (not history) and the view settings. Every scene edit is a named action that
 * pushes exactly one history entry (an edit that changes nothing pushes none).
 */
import { create } from 'zustand';
import { blankScene, sceneLights } from '../model/defaults';
import { pasteText } from '../model/clipboard';
import { carryIds } from '../model/identity';
import { roundEdit } from '../model/rounding';
import { sameJson } from '../model/sameJson';
import * as edits from '../model/edits';
import type { GizmoMode } from '../model/gizmo';
import { nudgeItems, removeItems, duplicateItems } from '../model/groupEdits';
import { isSceneItem, selectFound, selectOne, toggleItem, type DragTarget, type SceneItem, type Selection } from '../model/selection';
import { STARTER_SCENE } from '../model/starterScene';
import type {
  CameraSettings,
  Color,
  ImageSettings,
  Material,
  MaterialType,
  AddableType,
  PlacedModel,
  RenderSettings,
  Scene,
  SceneObject,
  Vec3,
} from '../model/types';
import type { FieldErrors } from '../model/standingErrors';
import { push, redo, undo, type Timeline } from './history';
import type { Bounds } from '../model/obj';

/** Zoom (SVG pixels per metre) and pan (the world point at the view's centre) of one view. */
export interface ViewState {
  zoom: number;
  pan: [number, number];
}

export type ViewKind = 'top' | 'side';

/** Who reported a server refusal: a Render, or the live ray-traced view. */
export type ErrorSource = 'render' | 'live';

/** The server's field errors for one scene it refused, kept with that scene to tell when each is fixed. */
export interface ServerErrors {
  /** The scene as it was sent. */
  scene: Scene;
  errors: FieldErrors;
}

export interface SceneState {
  /** The committed scene (what undo/redo, save and render use). */
  scene: Scene;
  /** Earlier scenes, oldest first. */
  past: Scene[];
  /** Undone scenes, next redo first. */
  future: Scene[];
  /** The scene while a drag or a field edit is under way; null otherwise. Never in history. */
  preview: Scene | null;
  /** The primary selection: what the inspector edits and the 3D handles hold. */
  selection: Selection;
  /**
   * Every object and light selected (Shift/Ctrl-click, box select), the primary among them; moving,
   * deleting, duplicating and copying act on all of them, each as one undo step. Empty when the
   * camera, its target or nothing is selected.
   */
  selectedItems: SceneItem[];
  views: Record<ViewKind, ViewState>;
  snap: boolean;
  /** Grid spacing in metres (also the snapping step). */
  gridSize: number;
  /** Bumped when a whole new scene arrives: the views zoom to fit it. */
  fitRequest: number;
  /** Bumped by New, Open and Examples: what belonged to the previous scene (errors, renders) goes. */
  documentId: number;
  /** The server's latest refusal from each source; null when it has none (cleared by a new document). */
  serverErrors: Record<ErrorSource, ServerErrors | null>;

  /** Records (or, with `{}`, clears) a source's field errors for the scene it sent. */
  reportServerErrors(source: ErrorSource, scene: Scene, errors: FieldErrors): void;
  loadScene(scene: Scene): void;
  /** Puts back a kept scene with its undo and redo steps (autosave, on start-up); not itself a step. */
  resetTo(scene: Scene, past: Scene[], future: Scene[]): void;
  newScene(): void;
  /** Replaces the scene but keeps the selection where it still exists (the JSON tab). */
  setScene(scene: Scene): void;
  setName(name: string): void;
  setBackground(color: Color): void;
  setAmbient(ambient: number): void;
  setImage(patch: Partial<ImageSettings>): void;
  setRender(patch: Partial<RenderSettings>): void;
  setCamera(patch: Partial<CameraSettings>): void;
  addObject(kind: AddableType): void;
  /** Adds a mesh of inline OBJ text with a uniform scale, resting on the floor in front of the camera, selected (one history entry). */
  addMesh(obj: string, scale: number): void;
  /**
   * Adds an imported mesh or glTF model (by asset id) standing on the floor in front of the camera,
   * clear of the others, selected (one history entry); `bounds`: its box in its own coordinates, when known.
   */
  addModel(model: PlacedModel, bounds?: Bounds): void;
  /** Replaces a mesh's triangles by inline OBJ text (its `file`, if any, goes). */
  setMeshObj(index: number, obj: string): void;
  /** Replaces a mesh's triangles by an uploaded OBJ asset's (its `obj` or `file`, if any, goes). */
  setMeshAsset(index: number, asset: string): void;
  addLight(): void;
  /** Adds an area light hanging above the camera's target, aimed at it, selected (one history entry). */
  addAreaLight(): void;
  duplicateSelected(): void;
  deleteSelected(): void;
  moveObject(index: number, to: Vec3): void;
  setObjectField(index: number, field: string, value: unknown): void;
  setMaterial(index: number, material: Material): void;
  setMaterialType(index: number, type: MaterialType): void;
  moveLight(index: number, to: Vec3): void;
  setLightField<K extends edits.LightField>(index: number, field: K, value: edits.LightFieldValue<K>): void;
  /** Moves an object, light, the camera or its target (one history entry). */
  moveTarget(target: DragTarget, to: Vec3): void;
  /** Selects this alone (a plain click). */
  select(selection: Selection): void;
  /** Shift/Ctrl-click: adds an object or light to the selection, or takes it out. */
  toggleSelect(selection: Selection): void;
  /** Box select: selects what was found, added to the selection with `add`. */
  selectBox(found: SceneItem[], add: boolean): void;
  /** Drag step of a multi-selection: previews every selected item moved by the same offset; not history. */
  dragItemsBy(by: Vec3): void;
  /** Moves every selected item by an offset (arrow keys); one history entry. */
  nudgeSelected(by: Vec3): void;
  /** Shows an uncommitted scene (drag in progress, field being typed); not history. */
  setPreview(scene: Scene | null): void;
  /** Drag step: previews the target at a new position; not history. */
  dragTo(target: DragTarget, to: Vec3): void;
  /** Ends a drag or an edit: the preview becomes one history entry if it differs. */
  commitPreview(): void;
  cancelPreview(): void;
  undo(): void;
  redo(): void;
  setView(kind: ViewKind, view: ViewState): void;
  setSnap(snap: boolean): void;
  setGridSize(size: number): void;
  /** Asks both plan views to zoom to the whole scene. */
  requestFit(): void;
  /** Which handles the 3D view shows on the selection (W move, E rotate, R scale). */
  gizmo: GizmoMode;
  setGizmo(mode: GizmoMode): void;
  /** Bumped by F: the 3D view frames the selection. */
  frameRequest: number;
  requestFrame(): void;
  /** Adds the objects and lights of pasted scene JSON (one history entry), selecting the first; false if the text is no scene. */
  pasteText(text: string): boolean;
  /** Replaces one object (the 3D view's handles); one history entry. */
  replaceObject(index: number, object: SceneObject): void;
}

export const DEFAULT_VIEWS: Record<ViewKind, ViewState> = {
  top: { zoom: 40, pan: [0, 0] },
  side: { zoom: 40, pan: [0, 1.5] },
};

type Data = Pick<
  SceneState,
  'scene' | 'past' | 'future' | 'preview' | 'selection' | 'selectedItems' | 'views' | 'snap' | 'gridSize' | 'fitRequest' | 'documentId' | 'serverErrors' | 'gizmo' | 'frameRequest'
>;

const NO_SERVER_ERRORS: Record<ErrorSource, ServerErrors | null> = { render: null, live: null };

function initialData(scene: Scene): Data {
  return {
    scene: carryIds(null, scene), past: [], future: [], preview: null, selection: null, selectedItems: [], views: structuredClone(DEFAULT_VIEWS), snap: false, gridSize: 0.5, fitRequest: 1,
    documentId: 1, serverErrors: NO_SERVER_ERRORS, gizmo: 'translate', frameRequest: 0,
  };
}

/** The selection if it still names something in the scene, else none. */
function keepValid(scene: Scene, selection: Selection): Selection {
  if (selection?.kind === 'object' && !scene.objects[selection.index]) return null;
  if (selection?.kind === 'light' && !sceneLights(scene)[selection.index]) return null;
  if (selection?.kind === 'lightAim' && sceneLights(scene)[selection.index]?.type !== 'area') return null;
  return selection;
}

/** A primary selection and the items selected with it. */
type Picked = { primary: Selection; items: SceneItem[] };

/** The selection and its items, each kept only if it still names something in the scene. */
function keepPicked(scene: Scene, picked: Picked): Pick<SceneState, 'selection' | 'selectedItems'> {
  const items = picked.items.filter((item) => keepValid(scene, item) !== null);
  const selection = keepValid(scene, picked.primary);
  return { selection, selectedItems: isSceneItem(selection) ? items : [] };
}

const sameScene = (a: Scene, b: Scene) => sameJson(a, b);

export const useSceneStore = create<SceneState>()((set, get) => {
  /** The single write path: one edit, one history entry (none if nothing changed). */
  const commit = (edit: (scene: Scene) => Scene, selection?: (next: Scene) => Selection | Picked, newDocument = false, exact = newDocument) => {
    const { scene, past, future, selection: current, selectedItems } = get();
    // a new document numbers its objects afresh; an edit carries the ids on. The numbers an edit
    // writes are saved rounded; a file or the JSON text keeps the digits it was written with.
    const next = carryIds(newDocument ? null : scene, exact ? edit(scene) : roundEdit(scene, edit(scene)));
    if (sameScene(next, scene)) {
      set({ preview: null });
      return;
    }
    const timeline = push<Scene>({ past, present: scene, future }, next);
    const chosen = selection ? selection(next) : { primary: current, items: selectedItems };
    const picked = chosen !== null && 'items' in chosen ? chosen : selectOne(chosen);
    set({ scene: next, past: timeline.past, future: timeline.future, preview: null, ...keepPicked(next, picked) });
  };
  const travel = (move: (t: Timeline<Scene>) => Timeline<Scene>) => {
    const { scene, past, future, selection, selectedItems } = get();
    const t = move({ past, present: scene, future });
    set({ scene: t.present, past: t.past, future: t.future, preview: null, ...keepPicked(t.present, { primary: selection, items: selectedItems }) });
  };
  return {
    ...initialData(structuredClone(STARTER_SCENE)),

    reportServerErrors: (source, scene, errors) => {
      const report = Object.keys(errors).length === 0 ? null : { scene, errors };
      if (report === null && get().serverErrors[source] === null) return;
      set({ serverErrors: { ...get().serverErrors, [source]: report } });
    },
    loadScene: (scene) => {
      commit(() => structuredClone(scene), () => null, true);
      set({ fitRequest: get().fitRequest + 1, documentId: get().documentId + 1, serverErrors: NO_SERVER_ERRORS });
    },
    resetTo: (scene, past, future) => {
      set({ ...initialData(scene), past, future, fitRequest: get().fitRequest + 1, documentId: get().documentId + 1 });
    },
    newScene: () => {
      commit(() => blankScene(), () => null, true);
      set({ fitRequest: get().fitRequest + 1, documentId: get().documentId + 1, serverErrors: NO_SERVER_ERRORS });
    },
    setScene: (scene) => commit(() => structuredClone(scene), undefined, false, true),
    setName: (name) => commit((s) => ({ ...s, name })),
    setBackground: (background) => commit((s) => ({ ...s, background })),
    setAmbient: (ambient) => commit((s) => ({ ...s, ambient })),
    setImage: (patch) => commit((s) => edits.setImage(s, patch)),
    setRender: (patch) => commit((s) => edits.setRender(s, patch)),
    setCamera: (patch) => commit((s) => edits.setCamera(s, patch)),
    addObject: (kind) => commit((s) => edits.addObject(s, kind), (n) => ({ kind: 'object', index: n.objects.length - 1 })),
    addMesh: (obj, scale) => commit((s) => edits.addMesh(s, obj, scale), (n) => ({ kind: 'object', index: n.objects.length - 1 })),
    addModel: (model, bounds) => commit((s) => edits.addModel(s, model, bounds), (n) => ({ kind: 'object', index: n.objects.length - 1 })),
    setMeshObj: (index, obj) => commit((s) => edits.setMeshObj(s, index, obj)),
    setMeshAsset: (index, asset) => commit((s) => edits.setMeshAsset(s, index, asset)),
    addLight: () => commit((s) => edits.addLight(s), (n) => ({ kind: 'light', index: sceneLights(n).length - 1 })),
    addAreaLight: () => commit((s) => edits.addAreaLight(s), (n) => ({ kind: 'light', index: sceneLights(n).length - 1 })),
    duplicateSelected: () => {
      const { selection: sel, selectedItems } = get();
      if (selectedItems.length > 1) {
        const { scene, copies } = duplicateItems(get().scene, selectedItems);
        commit(() => scene, () => ({ primary: copies[copies.length - 1] ?? null, items: copies }));
        return;
      }
      if (sel?.kind === 'object') commit((s) => edits.duplicateObject(s, sel.index), () => ({ kind: 'object', index: sel.index + 1 }));
      if (sel?.kind === 'light' || sel?.kind === 'lightAim') commit((s) => edits.duplicateLight(s, sel.index), () => ({ kind: 'light', index: sel.index + 1 }));
    },
    deleteSelected: () => {
      const { selection: sel, selectedItems } = get();
      if (selectedItems.length > 1) {
        commit((s) => removeItems(s, selectedItems), () => null);
        return;
      }
      if (sel?.kind === 'object') commit((s) => edits.removeObject(s, sel.index), () => null);
      if (sel?.kind === 'light' || sel?.kind === 'lightAim') commit((s) => edits.removeLight(s, sel.index), () => null);
    },
    moveObject: (index, to) => commit((s) => edits.moveObject(s, index, to)),
    setObjectField: (index, field, value) => commit((s) => edits.setObjectField(s, index, field, value)),
    setMaterial: (index, material) => commit((s) => edits.setMaterial(s, index, material)),
    setMaterialType: (index, type) =>
      commit((s) => edits.setMaterial(s, index, edits.changeMaterialType(s.objects[index]?.material, type))),
    moveLight: (index, to) => commit((s) => edits.moveLight(s, index, to)),
    setLightField: (index, field, value) => commit((s) => edits.setLightField(s, index, field, value)),
    moveTarget: (target, to) => commit((s) => edits.moveTarget(s, target, to)),
    select: (selection) => set(keepPicked(get().scene, selectOne(selection))),
    toggleSelect: (selection) => {
      const { scene, selectedItems, selection: primary } = get();
      set(keepPicked(scene, toggleItem(selectedItems, primary, selection)));
    },
    selectBox: (found, add) => {
      const { scene, selectedItems, selection: primary } = get();
      set(keepPicked(scene, selectFound(selectedItems, primary, found, add)));
    },
    dragItemsBy: (by) => set({ preview: carryIds(get().scene, roundEdit(get().scene, nudgeItems(get().scene, get().selectedItems, by))) }),
    nudgeSelected: (by) => commit((s) => nudgeItems(s, get().selectedItems, by)),

    setPreview: (preview) => set({ preview: preview && carryIds(get().scene, roundEdit(get().scene, preview)) }),
    dragTo: (target, to) => set({ preview: carryIds(get().scene, roundEdit(get().scene, edits.moveTarget(get().scene, target, to))) }),
    commitPreview: () => {
      const { preview } = get();
      if (preview) commit(() => preview);
    },
    cancelPreview: () => set({ preview: null }),
    undo: () => travel(undo),
    redo: () => travel(redo),

    setView: (kind, view) => set({ views: { ...get().views, [kind]: view } }),
    setSnap: (snap) => set({ snap }),
    setGridSize: (gridSize) => set({ gridSize: gridSize > 0 ? gridSize : get().gridSize }),
    requestFit: () => set({ fitRequest: get().fitRequest + 1 }),
    setGizmo: (gizmo) => set({ gizmo }),
    requestFrame: () => set({ frameRequest: get().frameRequest + 1 }),
    pasteText: (text) => {
      const pasted = pasteText(get().scene, text);
      if (pasted) commit(() => pasted.scene, () => ({ primary: pasted.selection, items: pasted.items }));
      return pasted !== null;
    },
    replaceObject: (index, object) => commit((s) => edits.replaceObject(s, index, object)),
  };
});

/** The scene the views draw: the preview while one is under way, else the committed scene. */
export const selectDisplayScene = (state: SceneState): Scene => state.preview ?? state.scene;

/** Puts the store back to a fresh state (tests, and a "reset" if ever needed). */
export function resetSceneStore(scene: Scene = STARTER_SCENE): void {
  useSceneStore.setState(initialData(structuredClone(scene)));
}
