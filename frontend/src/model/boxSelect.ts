/**
 * Box select in a plan view: the objects and lights whose anchor (a sphere's or box's centre, a
 * mesh's position, a light's position) the view draws inside a rectangle dragged on screen. Planes
 * have no place to hold on to and are picked by clicking. Pure.
 */
import { resolveLight, resolveObject, sceneLights } from './defaults';
import { objectAnchor, worldToSvg, type Vec2, type ViewKind, type ViewTransform } from './projection';
import type { SceneItem } from './selection';
import type { Scene } from './types';

/** The items drawn inside the rectangle with corners `a` and `b` (SVG pixels, any two opposite corners). */
export function itemsInRect(scene: Scene, kind: ViewKind, t: ViewTransform, a: Vec2, b: Vec2): SceneItem[] {
  const [x0, x1] = a[0] <= b[0] ? [a[0], b[0]] : [b[0], a[0]];
  const [y0, y1] = a[1] <= b[1] ? [a[1], b[1]] : [b[1], a[1]];
  const inside = (p: Vec2) => p[0] >= x0 && p[0] <= x1 && p[1] >= y0 && p[1] <= y1;
  const found: SceneItem[] = [];
  scene.objects.forEach((object, index) => {
    if (object.type === 'plane') return;
    if (inside(worldToSvg(kind, t, objectAnchor(resolveObject(object))))) found.push({ kind: 'object', index });
  });
  sceneLights(scene).forEach((light, index) => {
    if (inside(worldToSvg(kind, t, resolveLight(light).position))) found.push({ kind: 'light', index });
  });
  return found;
}
