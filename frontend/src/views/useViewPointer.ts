import { useCallback, useEffect, useLayoutEffect, useRef, useState, type FocusEvent as ReactFocusEvent, type KeyboardEvent as ReactKeyboardEvent, type PointerEvent as ReactPointerEvent, type RefObject } from 'react';
import { nudgeTarget, positionOf } from '../model/edits';
import { panBy, pixelStep, snapToGrid, svgToWorld, VIEW_AXES, worldToSvg, zoomAbout, type Vec2, type ViewKind, type ViewTransform } from '../model/projection';
import { itemsInRect } from '../model/boxSelect';
import { inItems, sameSelection, type DragTarget } from '../model/selection';
import type { Vec3 } from '../model/types';
import { useSceneStore } from '../store/sceneStore';

/** Pixels a pointer may wander before a press counts as a drag rather than a click. */
const CLICK_SLOP = 3;

type Gesture =
  | { mode: 'move'; target: DragTarget; start: Vec2; origin: Vec3; moved: boolean; pointer: number; group: boolean }
  | { mode: 'pan'; start: Vec2; t: ViewTransform; moved: boolean; pointer: number; button: number }
  | { mode: 'box'; start: Vec2; end: Vec2; moved: boolean; pointer: number };

/** The rectangle of a box select under way, in SVG pixels. */
export interface Marquee {
  x: number;
  y: number;
  width: number;
  height: number;
}

/** Shift, Ctrl or Cmd: a click adds to the selection or takes out, a drag on empty space box-selects. */
const adding = (event: { shiftKey: boolean; ctrlKey: boolean; metaKey: boolean }) => event.shiftKey || event.ctrlKey || event.metaKey;

/** Reads `data-target` ("object:2", "light:0", "lightAim:1", "camera", "target") of the pressed glyph. */
export function parseTarget(value: string | undefined): DragTarget | null {
  if (!value) return null;
  const [kind, index] = value.split(':');
  if (kind === 'object' || kind === 'light' || kind === 'lightAim') return { kind, index: Number(index) };
  if (kind === 'camera' || kind === 'target') return { kind };
  return null;
}

/**
 * Pointer handling of a plan view: press on a glyph selects it and dragging moves it (a
 * transient preview, committed as one undo step on release; snapped to the grid when snapping
 * is on), or moves the whole selection if the glyph is part of a multi-selection; Shift/Ctrl-click
 * adds a glyph to the selection or takes it out; press on empty space or with the middle button
 * pans, and with Shift/Ctrl draws a box that selects what lies inside; a click on empty space
 * clears the selection; the wheel zooms about the cursor. Uses pointer capture. Returns the
 * handlers for the SVG and the box being drawn.
 */
export function useViewPointer(kind: ViewKind, svgRef: RefObject<SVGSVGElement | null>, t: ViewTransform) {
  const gesture = useRef<Gesture | null>(null);
  /** True between a press and its release (focus a press gives is not a keyboard selection). */
  const pressed = useRef(false);
  const view = useRef(t);
  useLayoutEffect(() => {
    view.current = t;
  });
  const [marquee, setMarquee] = useState<Marquee | null>(null);

  const local = useCallback(
    (event: { clientX: number; clientY: number }): Vec2 => {
      if (!Number.isFinite(event.clientX) || !Number.isFinite(event.clientY)) return [view.current.width / 2, view.current.height / 2];
      const rect = svgRef.current?.getBoundingClientRect();
      return [event.clientX - (rect?.left ?? 0), event.clientY - (rect?.top ?? 0)];
    },
    [svgRef],
  );

  useEffect(() => {
    const svg = svgRef.current;
    if (!svg) return;
    const onWheel = (event: WheelEvent) => {
      event.preventDefault();
      const factor = Math.exp(-event.deltaY * (event.deltaMode === 1 ? 0.05 : 0.0015));
      useSceneStore.getState().setView(kind, zoomAbout(kind, view.current, local(event), factor));
    };
    svg.addEventListener('wheel', onWheel, { passive: false });
    return () => svg.removeEventListener('wheel', onWheel);
  }, [kind, svgRef, local]);

  const onPointerDown = (event: ReactPointerEvent<SVGSVGElement>) => {
    pressed.current = true;
    if (gesture.current || (event.button !== 0 && event.button !== 1)) return;
    const store = useSceneStore.getState();
    const hit = (event.target as Element).closest?.('[data-target]') as SVGElement | null;
    const target = event.button === 0 ? parseTarget(hit?.dataset.target) : null;
    const start = local(event);
    const origin = target ? positionOf(store.scene, target) : null;
    if (target && origin && adding(event)) {
      store.toggleSelect(target);
      event.preventDefault();
      return;
    }
    if (target && origin) {
      const group = store.selectedItems.length > 1 && inItems(store.selectedItems, target);
      if (!group) store.select(target);
      gesture.current = { mode: 'move', target, start, origin, moved: false, pointer: event.pointerId, group };
    } else if (event.button === 0 && adding(event)) {
      gesture.current = { mode: 'box', start, end: start, moved: false, pointer: event.pointerId };
    } else {
      gesture.current = { mode: 'pan', start, t: view.current, moved: false, pointer: event.pointerId, button: event.button };
    }
    // Leaving a half-typed inspector field commits it before the drag starts.
    const active = document.activeElement as HTMLElement | null;
    if (active && active !== document.body && !svgRef.current?.contains(active)) active.blur();
    event.preventDefault();
    try {
      svgRef.current?.setPointerCapture(event.pointerId);
    } catch {
      // Not every environment supports capture (tests); the handlers still work.
    }
  };

  const onPointerMove = (event: ReactPointerEvent<SVGSVGElement>) => {
    const g = gesture.current;
    if (!g || g.pointer !== event.pointerId) return;
    const [x, y] = local(event);
    const dx = x - g.start[0];
    const dy = y - g.start[1];
    if (!g.moved && Math.hypot(dx, dy) < CLICK_SLOP) return;
    g.moved = true;
    const store = useSceneStore.getState();
    if (g.mode === 'pan') {
      store.setView(kind, { zoom: g.t.zoom, pan: panBy(kind, g.t, dx, dy) });
      return;
    }
    if (g.mode === 'box') {
      g.end = [x, y];
      setMarquee({ x: Math.min(g.start[0], x), y: Math.min(g.start[1], y), width: Math.abs(dx), height: Math.abs(dy) });
      return;
    }
    const o = worldToSvg(kind, view.current, g.origin);
    let to = svgToWorld(kind, view.current, [o[0] + dx, o[1] + dy], g.origin);
    to = snapToGrid(kind, to, store.snap ? store.gridSize : pixelStep(view.current.zoom));
    if (g.group) store.dragItemsBy([to[0] - g.origin[0], to[1] - g.origin[1], to[2] - g.origin[2]]);
    else store.dragTo(g.target, to);
  };

  const finish = (event: ReactPointerEvent<SVGSVGElement>, cancelled: boolean) => {
    const g = gesture.current;
    if (!g || g.pointer !== event.pointerId) return;
    gesture.current = null;
    try {
      svgRef.current?.releasePointerCapture(event.pointerId);
    } catch {
      // see setPointerCapture
    }
    const store = useSceneStore.getState();
    if (g.mode === 'box') {
      setMarquee(null);
      if (!cancelled && g.moved) store.selectBox(itemsInRect(store.scene, kind, view.current, g.start, g.end), true);
    } else if (g.mode === 'move') {
      if (cancelled) store.cancelPreview();
      else if (g.moved) store.commitPreview();
      else if (g.group) store.select(g.target); // a click on one of several selected picks it alone
    } else if (!g.moved && !cancelled && g.button === 0) {
      store.select(null);
    }
  };

  /**
   * Keyboard: Enter/Space selects the focused glyph (Shift/Ctrl adds it or takes it out); arrow
   * keys move it one grid step, or the whole selection if it is part of one (one undo step each).
   */
  const onKeyDown = (event: ReactKeyboardEvent<SVGSVGElement>) => {
    const target = parseTarget(((event.target as Element).closest?.('[data-target]') as SVGElement | null)?.dataset.target);
    if (!target) return;
    const store = useSceneStore.getState();
    if (event.key === 'Enter' || event.key === ' ') {
      if (adding(event)) store.toggleSelect(target);
      else store.select(target);
      event.preventDefault();
      return;
    }
    const steps: Record<string, Vec2> = { ArrowLeft: [-1, 0], ArrowRight: [1, 0], ArrowUp: [0, -1], ArrowDown: [0, 1] };
    const step = steps[event.key];
    if (!step) return;
    const a = VIEW_AXES[kind];
    const by: Vec3 = [0, 0, 0];
    by[a.u] = step[0] * store.gridSize;
    by[a.v] = step[1] * a.down * store.gridSize;
    if (store.selectedItems.length > 1 && inItems(store.selectedItems, target)) {
      store.nudgeSelected(by);
    } else {
      store.select(target);
      store.setPreview(nudgeTarget(store.scene, target, by));
      store.commitPreview();
    }
    event.preventDefault();
  };

  /**
   * Focus reaching a glyph from the keyboard (Tab) selects it, as a click does; focus a press gives
   * is left to the press (a Shift-click that takes a glyph out of the selection keeps it out).
   */
  const onFocus = (event: ReactFocusEvent<SVGSVGElement>) => {
    if (pressed.current) return;
    const target = parseTarget(((event.target as Element).closest?.('[data-target]') as SVGElement | null)?.dataset.target);
    const store = useSceneStore.getState();
    if (!target || sameSelection(store.selection, target) || inItems(store.selectedItems, target)) return;
    store.select(target);
  };

  return {
    marquee,
    handlers: {
      onKeyDown,
      onFocus,
      onPointerDown,
      onPointerMove,
      onPointerUp: (event: ReactPointerEvent<SVGSVGElement>) => {
        pressed.current = false;
        finish(event, false);
      },
      onPointerCancel: (event: ReactPointerEvent<SVGSVGElement>) => {
        pressed.current = false;
        finish(event, true);
      },
    },
  };
}
