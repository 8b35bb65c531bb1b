/**
 * Arrow keys in the 3D and ray-traced views: the selection moves one grid step along the world
 * axis nearest the direction the key points on screen (Left/Right: the camera's right; Up/Down:
 * away from and towards the camera along the floor; with Shift, Up/Down: up and down), so that
 * what is seen moves the way the arrow points, as the plan views' arrows do.
 */
import { nudgeTarget } from '../model/edits';
import type { Vec3 } from '../model/types';
import { useSceneStore } from '../store/sceneStore';

/** The floor axis (x or z) nearest `v`, as a unit vector with its sign; `not` is an axis it must not be. */
function floorAxis(v: Vec3, not?: 0 | 2): { axis: 0 | 2; sign: number } {
  let axis: 0 | 2 = Math.abs(v[0]) >= Math.abs(v[2]) ? 0 : 2;
  if (axis === not) axis = axis === 0 ? 2 : 0;
  return { axis, sign: v[axis] < 0 ? -1 : 1 };
}

/**
 * How far one press of `key` moves the selection in a view whose camera looks along `forward` with
 * `right` to its right; null for a key that is no arrow.
 */
export function nudgeStep(key: string, shift: boolean, forward: Vec3, right: Vec3, grid: number): Vec3 | null {
  const by: Vec3 = [0, 0, 0];
  if (shift && (key === 'ArrowUp' || key === 'ArrowDown')) {
    by[1] = key === 'ArrowUp' ? grid : -grid;
    return by;
  }
  const side = floorAxis(right);
  const ahead = floorAxis(forward, side.axis);
  if (key === 'ArrowLeft' || key === 'ArrowRight') by[side.axis] = side.sign * grid * (key === 'ArrowRight' ? 1 : -1);
  else if (key === 'ArrowUp' || key === 'ArrowDown') by[ahead.axis] = ahead.sign * grid * (key === 'ArrowUp' ? 1 : -1);
  else return null;
  return by;
}

/** Moves the selection (all of a multi-selection) by `by`, one undo step; false when nothing is selected. */
export function nudgeSelection(by: Vec3): boolean {
  const store = useSceneStore.getState();
  if (store.selectedItems.length > 1) {
    store.nudgeSelected(by);
    return true;
  }
  if (!store.selection) return false;
  store.setPreview(nudgeTarget(store.scene, store.selection, by));
  store.commitPreview();
  return true;
}
