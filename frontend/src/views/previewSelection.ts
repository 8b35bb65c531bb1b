/**
 * The store's side of the 3D preview's direct manipulation: which handles the selection gets, what
 * a handle movement does to the scene (a transient preview) and its release (one history entry),
 * and the ball F frames.
 */
import { resolveScene } from '../model/defaults';
import { applyGizmo, gizmoModes, gizmoPose, objectBall, roundVec, type GizmoMode, type GizmoPose } from '../model/gizmo';
import type { MeshLookup } from '../model/meshCache';
import type { Selection } from '../model/selection';
import type { Scene, Vec3 } from '../model/types';
import { aimLight, moveLight, positionOf, replaceObject } from '../model/edits';
import { useSceneStore } from '../store/sceneStore';
import type { HandleCallbacks } from './previewHandles';

/** The handles a selection has, where they start; null for none (the camera is moved in the plan views). */
export function handlesFor(scene: Scene, selection: Selection): { pose: GizmoPose; modes: GizmoMode[] } | null {
  if (selection?.kind === 'object') {
    const object = scene.objects[selection.index];
    return object ? { pose: gizmoPose(object), modes: gizmoModes(object) } : null;
  }
  if (selection?.kind === 'light' || selection?.kind === 'lightAim') {
    // an area light moves by its centre (it keeps facing its aim), and turns by its aim
    const position = positionOf(scene, selection);
    return position ? { pose: { position, rotation: [0, 0, 0], scale: [1, 1, 1] }, modes: ['translate'] } : null;
  }
  return null;
}

/** The scene with the selection where the handles put it (rounded to a millimetre, or the grid when snapping). */
export function posedScene(scene: Scene, selection: Selection, pose: GizmoPose, step: number): Scene {
  if (selection?.kind === 'object') {
    const object = scene.objects[selection.index];
    return object ? replaceObject(scene, selection.index, applyGizmo(object, pose, step)) : scene;
  }
  if (selection?.kind === 'light') return moveLight(scene, selection.index, roundVec(pose.position, step));
  if (selection?.kind === 'lightAim') return aimLight(scene, selection.index, roundVec(pose.position, step));
  return scene;
}

/** What F frames: the selection's extent, or with nothing selected every object. */
export function selectionBall(scene: Scene, selection: Selection, meshes: MeshLookup): { center: Vec3; radius: number } {
  if (selection?.kind === 'object' && scene.objects[selection.index]) return objectBall(scene.objects[selection.index], meshes);
  const r = resolveScene(scene);
  if ((selection?.kind === 'light' || selection?.kind === 'lightAim') && r.lights[selection.index]) {
    const light = r.lights[selection.index];
    const center = selection.kind === 'lightAim' && light.type === 'area' ? light.lookAt : light.position;
    const radius = light.type === 'area' && selection.kind === 'light' ? Math.max(0.5, Math.hypot(...light.size) / 2) : light.type === 'point' ? Math.max(0.5, light.radius) : 0.5;
    return { center, radius };
  }
  if (selection?.kind === 'camera') return { center: r.camera.position, radius: 0.5 };
  if (selection?.kind === 'target') return { center: r.camera.lookAt, radius: 0.5 };
  const balls = scene.objects.filter((o) => o.type !== 'plane').map((o) => objectBall(o, meshes));
  if (balls.length === 0) return { center: r.camera.lookAt, radius: 2 };
  const min = [0, 1, 2].map((k) => Math.min(...balls.map((b) => b.center[k] - b.radius)));
  const max = [0, 1, 2].map((k) => Math.max(...balls.map((b) => b.center[k] + b.radius)));
  return { center: [0, 1, 2].map((k) => (min[k] + max[k]) / 2) as Vec3, radius: Math.hypot(max[0] - min[0], max[1] - min[1], max[2] - min[2]) / 2 };
}

/** The preview's handle events as store actions: a pick selects, a drag previews, the release commits once. */
export const handleCallbacks: Pick<HandleCallbacks, 'onPick' | 'onPose' | 'onRelease'> = {
  onPick: (target, adding) => {
    const s = useSceneStore.getState();
    if (adding && target) s.toggleSelect(target);
    else if (!adding) s.select(target);
  },
  onPose: (pose) => {
    const s = useSceneStore.getState();
    s.setPreview(posedScene(s.scene, s.selection, pose, s.snap ? s.gridSize : 0.001));
  },
  onRelease: () => useSceneStore.getState().commitPreview(),
};
