import { act, createEvent, fireEvent, render as rtlRender, screen, waitFor, within } from '@testing-library/react';
import type { ReactElement } from 'react';
import { describe, expect, it } from 'vitest';
import { worldToSvg, type ViewTransform } from '../model/projection';
import type { Scene } from '../model/types';
import { DEFAULT_VIEWS, resetSceneStore, useSceneStore } from '../store/sceneStore';
import { meshCache } from '../hooks/useMeshes';
import { gridObj, TETRAHEDRON_OBJ } from '../test/meshes';
import { SideView } from './SideView';
import { TopView } from './TopView';

const store = () => useSceneStore.getState();
/** The views measure 480 x 320 in tests (no layout); default zoom 40 px/m. */
const top = (): ViewTransform => ({ ...store().views.top, width: 480, height: 320 });
const side = (): ViewTransform => ({ ...store().views.side, width: 480, height: 320 });

const SCENE: Scene = {
  name: 'views',
  camera: { position: [0, 2, 8], lookAt: [0, 0, 0] },
  lights: [{ type: 'point', position: [2, 5, -1], color: '#ffcc00' }],
  objects: [
    { type: 'sphere', center: [1, 1, 2], radius: 0.5, material: { type: 'mirror' } },
    { type: 'box', center: [-2, 0.5, 0], size: [2, 1, 1], rotation: [0, 90, 0] },
    { type: 'plane', point: [0, 0, 0], normal: [0, 1, 0] },
  ],
};

/** Renders, then puts both views at the default zoom (40 px/m) and pan the tests reason in. */
function render(ui: ReactElement) {
  const utils = rtlRender(ui);
  act(() => {
    store().setView('top', { zoom: 40, pan: [0, 0] });
    store().setView('side', DEFAULT_VIEWS.side);
  });
  return utils;
}

function drag(element: Element, svg: Element, from: [number, number], by: [number, number], steps = 5) {
  fireEvent.pointerDown(element, { clientX: from[0], clientY: from[1], button: 0, pointerId: 1 });
  for (let i = 1; i <= steps; i++) {
    fireEvent.pointerMove(svg, { clientX: from[0] + (by[0] * i) / steps, clientY: from[1] + (by[1] * i) / steps, pointerId: 1 });
  }
  fireEvent.pointerUp(svg, { clientX: from[0] + by[0], clientY: from[1] + by[1], pointerId: 1 });
}

describe('top and side views', () => {
  it('draw every object, light, the camera and its target where the projection puts them', () => {
    resetSceneStore(SCENE);
    render(<><TopView /><SideView /></>);
    const topSvg = screen.getByTestId('top-view');
    const sphere = within(topSvg).getByTestId('object-0');
    expect(sphere).toHaveAttribute('data-kind', 'sphere');
    const circle = sphere.querySelector('circle')!;
    const [x, y] = worldToSvg('top', top(), [1, 1, 2]);
    expect(Number(circle.getAttribute('cx'))).toBeCloseTo(x);
    expect(Number(circle.getAttribute('cy'))).toBeCloseTo(y);
    expect(Number(circle.getAttribute('r'))).toBeCloseTo(0.5 * 40);
    // A box turned 90° about y shows its 2 m side along z.
    const points = within(topSvg).getByTestId('object-1').querySelector('polygon')!.getAttribute('points')!;
    const ys = points.split(' ').map((p) => Number(p.split(',')[1]));
    expect(Math.max(...ys) - Math.min(...ys)).toBeCloseTo(80);
    expect(within(topSvg).getByTestId('object-2')).toHaveAttribute('data-kind', 'plane');
    expect(within(topSvg).getByTestId('light-0')).toBeInTheDocument();
    expect(within(topSvg).getByTestId('camera')).toBeInTheDocument();
    expect(within(topSvg).getByTestId('camera-target')).toBeInTheDocument();
    // The side view sees the floor edge-on: a line.
    const sideSvg = screen.getByTestId('side-view');
    expect(within(sideSvg).getByTestId('object-2').querySelector('line.plane-line')).not.toBeNull();
    const sideCircle = within(sideSvg).getByTestId('object-0').querySelector('circle')!;
    expect(Number(sideCircle.getAttribute('cx'))).toBeCloseTo(x);
    expect(Number(sideCircle.getAttribute('cy'))).toBeCloseTo(worldToSvg('side', side(), [1, 1, 2])[1]);
  });

  it('select on click and show the selection in both views', () => {
    resetSceneStore(SCENE);
    render(<><TopView /><SideView /></>);
    const [x, y] = worldToSvg('top', top(), [1, 1, 2]);
    const glyph = within(screen.getByTestId('top-view')).getByTestId('object-0');
    fireEvent.pointerDown(glyph, { clientX: x, clientY: y, button: 0, pointerId: 1 });
    fireEvent.pointerUp(screen.getByTestId('top-view'), { clientX: x, clientY: y, pointerId: 1 });
    expect(store().selection).toEqual({ kind: 'object', index: 0 });
    expect(store().past).toHaveLength(0);
    expect(within(screen.getByTestId('side-view')).getByTestId('object-0')).toHaveAttribute('data-selected', 'true');
    // A click on empty space clears the selection.
    fireEvent.pointerDown(screen.getByTestId('top-view'), { clientX: 5, clientY: 5, button: 0, pointerId: 2 });
    fireEvent.pointerUp(screen.getByTestId('top-view'), { clientX: 5, clientY: 5, pointerId: 2 });
    expect(store().selection).toBeNull();
  });

  it('move an object by dragging it, as one undo step, x and z in the top view', () => {
    resetSceneStore(SCENE);
    render(<><TopView /><SideView /></>);
    const svg = screen.getByTestId('top-view');
    const from = worldToSvg('top', top(), [1, 1, 2]);
    drag(within(svg).getByTestId('object-0'), svg, from, [40, 20]);
    expect(store().scene.objects[0]).toMatchObject({ center: [2, 1, 2.5] });
    expect(store().past).toHaveLength(1);
    expect(store().preview).toBeNull();
    const sideCircle = within(screen.getByTestId('side-view')).getByTestId('object-0').querySelector('circle')!;
    expect(Number(sideCircle.getAttribute('cx'))).toBeCloseTo(worldToSvg('side', side(), [2, 1, 2.5])[0]);
    store().undo();
    expect(store().scene.objects[0]).toMatchObject({ center: [1, 1, 2] });
  });

  it('move x and y in the side view, snapping to the grid when asked', () => {
    resetSceneStore(SCENE);
    store().setSnap(true);
    render(<SideView />);
    const svg = screen.getByTestId('side-view');
    drag(within(svg).getByTestId('light-0'), svg, worldToSvg('side', side(), [2, 5, -1]), [13, -31]);
    // 13 px = 0.325 m and 31 px = 0.775 m, snapped to the 0.5 m grid.
    expect(store().scene.lights?.[0].position).toEqual([2.5, 6, -1]);
    expect(store().past).toHaveLength(1);
  });

  it('drag the camera and its target', () => {
    resetSceneStore(SCENE);
    render(<TopView />);
    const svg = screen.getByTestId('top-view');
    drag(within(svg).getByTestId('camera-target'), svg, worldToSvg('top', top(), [0, 0, 0]), [-40, 0]);
    expect(store().scene.camera?.lookAt).toEqual([-1, 0, 0]);
    drag(within(svg).getByTestId('camera'), svg, worldToSvg('top', top(), [0, 2, 8]), [0, -40]);
    expect(store().scene.camera?.position).toEqual([0, 2, 7]);
    expect(store().past).toHaveLength(2);
  });

  it('pan on a drag over empty space and zoom about the cursor with the wheel', () => {
    resetSceneStore(SCENE);
    render(<TopView />);
    const svg = screen.getByTestId('top-view');
    drag(svg, svg, [10, 10], [40, 80]);
    expect(store().views.top.pan).toEqual([-1, -2]);
    // Fit zooms to the whole scene: every point of it inside the view.
    fireEvent.click(screen.getByRole('button', { name: 'Fit' }));
    for (const p of [[0, 2, 8], [2, 5, -1], [-3, 0.5, 0]] as const) {
      const [x, y] = worldToSvg('top', top(), [...p]);
      expect(x).toBeGreaterThan(0);
      expect(x).toBeLessThan(480);
      expect(y).toBeGreaterThan(0);
      expect(y).toBeLessThan(320);
    }
    act(() => store().setView('top', { zoom: 40, pan: [-1, -2] }));
    const under = worldToSvg('top', top(), [3, 0, 1]);
    const wheel = createEvent.wheel(svg, { deltaY: -200 });
    // happy-dom's WheelEvent has no pointer position; a browser's has.
    Object.defineProperties(wheel, { clientX: { value: under[0] }, clientY: { value: under[1] } });
    fireEvent(svg, wheel);
    expect(store().views.top.zoom).toBeGreaterThan(40);
    const after = worldToSvg('top', top(), [3, 0, 1]);
    expect(after[0]).toBeCloseTo(under[0], 6);
    expect(after[1]).toBeCloseTo(under[1], 6);
    expect(store().past).toHaveLength(0);
  });
});

describe('keyboard in the views', () => {
  it('moves the focused glyph one grid step per arrow key, one undo step each', () => {
    resetSceneStore(SCENE);
    render(<><TopView /><SideView /></>);
    const sphere = within(screen.getByTestId('top-view')).getByTestId('object-0');
    fireEvent.keyDown(sphere, { key: 'ArrowRight' });
    fireEvent.keyDown(sphere, { key: 'ArrowUp' });
    expect(store().scene.objects[0]).toMatchObject({ center: [1.5, 1, 1.5] });
    expect(store().selection).toEqual({ kind: 'object', index: 0 });
    fireEvent.keyDown(within(screen.getByTestId('side-view')).getByTestId('light-0'), { key: 'ArrowUp' });
    expect(store().scene.lights?.[0].position).toEqual([2, 5.5, -1]);
    expect(store().past).toHaveLength(3);
  });

  it('selects a glyph that Tab focuses, and leaves a press its own choice', () => {
    resetSceneStore(SCENE);
    render(<TopView />);
    const view = screen.getByTestId('top-view');
    act(() => within(view).getByTestId('object-1').focus());
    expect(store().selection).toEqual({ kind: 'object', index: 1 });
    act(() => within(view).getByTestId('light-0').focus());
    expect(store().selection).toEqual({ kind: 'light', index: 0 });
    expect(store().past).toHaveLength(0); // selecting is no edit
    // a Shift-press takes the light out of a selection of two; the focus it gives does not put it back
    act(() => store().toggleSelect({ kind: 'object', index: 0 }));
    const light = within(view).getByTestId('light-0');
    fireEvent.pointerDown(light, { button: 0, pointerId: 1, shiftKey: true });
    act(() => within(view).getByTestId('object-1').focus());
    act(() => light.focus());
    fireEvent.pointerUp(light, { button: 0, pointerId: 1, shiftKey: true });
    expect(store().selection).toEqual({ kind: 'object', index: 0 });
  });
});

describe('meshes in the views', () => {
  // The tetrahedron scaled by 2 and turned 90° about z: its corners (2,0,0), (0,2,0), (0,0,2) go to
  // (0,2,0), (-2,0,0), (0,0,2); moved to (1, 0.5, -1) its bounds are x -1..1, y 0.5..2.5, z -1..1.
  const MESH_SCENE: Scene = {
    ...SCENE,
    objects: [
      { type: 'sphere', center: [3, 1, 0], radius: 0.5 },
      { type: 'mesh', obj: TETRAHEDRON_OBJ, position: [1, 0.5, -1], scale: 2, rotation: [0, 0, 90], material: { type: 'plastic', color: '#336699' } },
      { type: 'mesh', file: 'meshes/torus-knot.obj', position: [-2, 1, 0] },
    ],
  };

  /** The rectangle of a mesh glyph, as numbers. */
  const rectOf = (view: HTMLElement, index: number) => {
    const rect = within(view).getByTestId(`object-${index}`).querySelector('rect.mesh-outline')!;
    return ['x', 'y', 'width', 'height'].map((a) => Number(rect.getAttribute(a)));
  };

  it('draw a mesh as the dashed rectangle its world bounds cover, labelled, in both views', () => {
    resetSceneStore(MESH_SCENE);
    render(<><TopView /><SideView /></>);
    const topView = screen.getByTestId('top-view');
    const sideView = screen.getByTestId('side-view');
    // Top: x -1..1 to the right, z -1..1 down the screen.
    const [tx0, ty0] = worldToSvg('top', top(), [-1, 0, -1]);
    const [tx1, ty1] = worldToSvg('top', top(), [1, 0, 1]);
    expect(rectOf(topView, 1)).toEqual([tx0, ty0, tx1 - tx0, ty1 - ty0].map((v) => expect.closeTo(v, 6)));
    // Side: x -1..1, y 0.5..2.5 up the screen (so the top edge is at y = 2.5).
    const [sx0, sy0] = worldToSvg('side', side(), [-1, 2.5, 0]);
    const [sx1, sy1] = worldToSvg('side', side(), [1, 0.5, 0]);
    expect(rectOf(sideView, 1)).toEqual([sx0, sy0, sx1 - sx0, sy1 - sy0].map((v) => expect.closeTo(v, 6)));
    expect(sx0).toBeCloseTo(tx0); // the two views agree on x
    const glyph = within(topView).getByTestId('object-1');
    expect(glyph).toHaveAttribute('data-kind', 'mesh');
    expect(glyph).toHaveAccessibleName('Mesh 2 (4 triangles)');
    expect(glyph.querySelector('text')).toHaveTextContent('Mesh 2');
    expect(glyph.querySelector('rect')).toHaveAttribute('fill', '#336699');
  });

  it('show a mesh whose file is still loading as a small labelled square at its position', () => {
    resetSceneStore(MESH_SCENE);
    render(<TopView />);
    const glyph = within(screen.getByTestId('top-view')).getByTestId('object-2');
    const [x, y, w, h] = rectOf(screen.getByTestId('top-view'), 2);
    const [px, py] = worldToSvg('top', top(), [-2, 1, 0]);
    expect([x + w / 2, y + h / 2]).toEqual([expect.closeTo(px, 6), expect.closeTo(py, 6)]);
    expect(w).toBeCloseTo(0.5 * 40);
    expect(glyph.querySelector('text')).toHaveTextContent('Mesh 3 (loading…)');
  });

  it('select and drag a mesh by its rectangle: only its position moves, one undo step', () => {
    resetSceneStore(MESH_SCENE);
    render(<><TopView /><SideView /></>);
    const svg = screen.getByTestId('top-view');
    const rect = within(svg).getByTestId('object-1').querySelector('rect')!;
    // Press inside the rectangle, away from the position dot.
    drag(rect, svg, worldToSvg('top', top(), [0, 0, 0]), [40, 80]);
    expect(store().selection).toEqual({ kind: 'object', index: 1 });
    expect(store().scene.objects[1]).toEqual({ ...MESH_SCENE.objects[1], position: [2, 0.5, 1] });
    expect(store().past).toHaveLength(1);
    const [tx0] = worldToSvg('top', top(), [0, 0, 0]);
    expect(rectOf(svg, 1)[0]).toBeCloseTo(tx0);
    expect(rectOf(screen.getByTestId('side-view'), 1)[0]).toBeCloseTo(tx0);
  });

  it('zoom out to a mesh file that arrives after the scene was fitted, unless the view was moved', async () => {
    const scene: Scene = { ...MESH_SCENE, objects: [{ type: 'mesh', file: 'meshes/wide.obj' }, { type: 'mesh', file: 'meshes/later.obj' }] };
    rtlRender(<TopView />);
    act(() => store().loadScene(scene));
    const fitted = store().views.top.zoom;
    act(() => meshCache.ensure('meshes/wide.obj', async () => gridObj(2, 30)));
    await waitFor(() => expect(store().views.top.zoom).toBeLessThan(fitted / 3));
    const [x] = worldToSvg('top', { ...store().views.top, width: 480, height: 320 }, [30, 0, 30]);
    expect(x).toBeLessThan(480);
    // Once the user zooms or pans, an arriving mesh leaves the view alone.
    act(() => store().setView('top', { zoom: 40, pan: [0, 0] }));
    act(() => meshCache.ensure('meshes/later.obj', async () => gridObj(2, 90)));
    await waitFor(() => expect(within(screen.getByTestId('top-view')).getByTestId('object-1')).toHaveAccessibleName('Mesh 2 (8 triangles)'));
    expect(store().views.top).toEqual({ zoom: 40, pan: [0, 0] });
  });
});

describe('multi-selection in the views', () => {
  const shiftClick = (el: Element) => {
    fireEvent.pointerDown(el, { clientX: 0, clientY: 0, button: 0, pointerId: 2, shiftKey: true });
    fireEvent.pointerUp(el, { clientX: 0, clientY: 0, pointerId: 2 });
  };

  it('Shift-click adds and takes out; dragging one of the group moves all of it as one undo step', () => {
    resetSceneStore(SCENE);
    render(<><TopView /><SideView /></>);
    const svg = screen.getByTestId('top-view');
    const sphere = within(svg).getByTestId('object-0');
    fireEvent.pointerDown(sphere, { clientX: 0, clientY: 0, button: 0, pointerId: 1 });
    fireEvent.pointerUp(svg, { clientX: 0, clientY: 0, pointerId: 1 });
    shiftClick(within(svg).getByTestId('object-1'));
    shiftClick(within(svg).getByTestId('light-0'));
    expect(store().selectedItems).toHaveLength(3);
    for (const id of ['object-0', 'object-1', 'light-0']) expect(within(svg).getByTestId(id)).toHaveAttribute('data-selected', 'true');
    expect(within(screen.getByTestId('side-view')).getByTestId('object-1')).toHaveAttribute('data-selected', 'true');
    // 40 px right and 40 px down in the top view: +1 m on x and z for all three
    drag(sphere.querySelector('circle')!, svg, worldToSvg('top', top(), [1, 1, 2]), [40, 40]);
    expect(store().scene.objects[0]).toMatchObject({ center: [2, 1, 3] });
    expect(store().scene.objects[1]).toMatchObject({ center: [-1, 0.5, 1] });
    expect(store().scene.lights?.[0].position).toEqual([3, 5, 0]);
    expect(store().scene.objects[2]).toEqual(SCENE.objects[2]);
    expect(store().past).toHaveLength(1);
    expect(store().selectedItems).toHaveLength(3);
    // Shift-click again takes one out; a plain click on a member picks it alone
    shiftClick(within(svg).getByTestId('light-0'));
    expect(store().selectedItems).toEqual([{ kind: 'object', index: 0 }, { kind: 'object', index: 1 }]);
    fireEvent.pointerDown(within(svg).getByTestId('object-1'), { clientX: 5, clientY: 5, button: 0, pointerId: 3 });
    fireEvent.pointerUp(svg, { clientX: 5, clientY: 5, pointerId: 3 });
    expect(store().selectedItems).toEqual([{ kind: 'object', index: 1 }]);
    expect(store().past).toHaveLength(1);
  });

  it('Shift-drag on empty space draws a box and selects what lies inside; a plain drag still pans', () => {
    resetSceneStore(SCENE);
    render(<TopView />);
    const svg = screen.getByTestId('top-view');
    const from = worldToSvg('top', top(), [-3, 0, -2]);
    const to = worldToSvg('top', top(), [1.5, 0, 2.5]);
    fireEvent.pointerDown(svg, { clientX: from[0], clientY: from[1], button: 0, pointerId: 1, shiftKey: true });
    fireEvent.pointerMove(svg, { clientX: to[0], clientY: to[1], pointerId: 1 });
    const marquee = screen.getByTestId('marquee');
    expect(Number(marquee.getAttribute('width'))).toBeCloseTo(to[0] - from[0]);
    fireEvent.pointerUp(svg, { clientX: to[0], clientY: to[1], pointerId: 1 });
    expect(screen.queryByTestId('marquee')).toBeNull();
    // the sphere (1, _, 2), the box (-2, _, 0) and the light (2, _, -1)? x 2 is outside
    expect(store().selectedItems).toEqual([{ kind: 'object', index: 0 }, { kind: 'object', index: 1 }]);
    expect(store().views.top.pan).toEqual([0, 0]);
    drag(svg, svg, from, [40, 0]);
    expect(store().views.top.pan).not.toEqual([0, 0]);
  });

  it('arrow keys on a member move the whole selection one grid step', () => {
    resetSceneStore(SCENE);
    render(<TopView />);
    act(() => {
      store().select({ kind: 'object', index: 0 });
      store().toggleSelect({ kind: 'object', index: 1 });
    });
    fireEvent.keyDown(within(screen.getByTestId('top-view')).getByTestId('object-1'), { key: 'ArrowRight' });
    expect(store().scene.objects[0]).toMatchObject({ center: [1.5, 1, 2] });
    expect(store().scene.objects[1]).toMatchObject({ center: [-1.5, 0.5, 0] });
    expect(store().past).toHaveLength(1);
  });
});
