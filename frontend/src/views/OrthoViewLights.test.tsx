import { act, fireEvent, render as rtlRender, screen, within } from '@testing-library/react';
import type { ReactElement } from 'react';
import { describe, expect, it } from 'vitest';
import { itemsInRect } from '../model/boxSelect';
import { scenePoints } from '../model/bounds';
import { worldToSvg, type ViewTransform } from '../model/projection';
import type { Scene } from '../model/types';
import { DEFAULT_VIEWS, resetSceneStore, useSceneStore } from '../store/sceneStore';
import { SideView } from './SideView';
import { TopView } from './TopView';

const store = () => useSceneStore.getState();
/** The views measure 480 x 320 in tests (no layout); zoom 40 px/m. */
const top = (): ViewTransform => ({ ...store().views.top, width: 480, height: 320 });
const side = (): ViewTransform => ({ ...store().views.side, width: 480, height: 320 });

const SCENE: Scene = {
  objects: [{ type: 'plane' }],
  lights: [
    { type: 'point', position: [2, 5, -1], color: '#ffcc00', radius: 0.5 },
    { type: 'area', position: [0, 3, 0], size: [2, 1], lookAt: [0, 0, 0], color: '#ffeedd' },
    { type: 'area', position: [-3, 1, 0], size: [1, 2], lookAt: [0, 1, 0], twoSided: true },
  ],
};

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

/** The extent in SVG pixels of a polygon's points along x (0) or y (1). */
function span(polygon: Element, axis: 0 | 1): number {
  const values = polygon.getAttribute('points')!.split(' ').map((p) => Number(p.split(',')[axis]));
  return Math.max(...values) - Math.min(...values);
}

describe('lights in the top and side views', () => {
  it('draw a sphere light’s radius to scale around its sun', () => {
    resetSceneStore(SCENE);
    render(<TopView />);
    const circle = within(screen.getByTestId('top-view')).getByTestId('light-radius-0');
    expect(Number(circle.getAttribute('r'))).toBeCloseTo(0.5 * 40);
    act(() => store().setLightField(0, 'radius', 0));
    expect(screen.queryByTestId('light-radius-0')).toBeNull();
  });

  it('draw an area light facing down as its rectangle from above and as a line from the side, with its aim', () => {
    resetSceneStore(SCENE);
    render(<><TopView /><SideView /></>);
    const topSvg = screen.getByTestId('top-view');
    const rect = within(topSvg).getByTestId('light-1').querySelector('polygon')!;
    expect(span(rect, 0)).toBeCloseTo(2 * 40, 3);
    expect(span(rect, 1)).toBeCloseTo(1 * 40, 1);
    expect(within(topSvg).queryByTestId('light-front-1')).toBeNull(); // it faces into the top view
    const sideSvg = screen.getByTestId('side-view');
    const edge = within(sideSvg).getByTestId('light-1').querySelector('polygon')!;
    expect(span(edge, 1)).toBeCloseTo(0, 0);
    const front = within(sideSvg).getByTestId('light-front-1').getAttribute('d')!;
    const [, x0, y0, x1, y1] = /M (\S+) (\S+) L (\S+) (\S+)/.exec(front)!.map(Number);
    expect(x1 - x0).toBeCloseTo(0, 0);
    expect(y1).toBeGreaterThan(y0); // it shines down the screen, towards y = 0
    const [ax, ay] = worldToSvg('side', side(), [0, 0, 0]);
    expect(within(sideSvg).getByTestId('light-aim-1').getAttribute('transform')).toBe(`translate(${ax} ${ay})`);
    expect(within(sideSvg).getAllByTestId('light-front-2')).toHaveLength(2); // two-sided: both ways
  });

  it('move an area light by dragging it (its aim stays) and turn it by dragging its aim, one undo step each', () => {
    resetSceneStore(SCENE);
    render(<TopView />);
    const svg = screen.getByTestId('top-view');
    // seen from above its aim is at its centre, drawn on top (later): the light is grabbed by its rectangle
    const [body, aim] = [within(svg).getByTestId('light-1'), within(svg).getByTestId('light-aim-1')];
    expect(body.compareDocumentPosition(aim) & Node.DOCUMENT_POSITION_FOLLOWING).toBeTruthy();
    drag(within(svg).getByTestId('light-1'), svg, worldToSvg('top', top(), [0.75, 3, 0.3]), [40, 0]);
    expect(store().scene.lights![1]).toMatchObject({ position: [1, 3, 0], lookAt: [0, 0, 0] });
    expect(store().selection).toEqual({ kind: 'light', index: 1 });
    drag(within(svg).getByTestId('light-aim-1'), svg, worldToSvg('top', top(), [0, 0, 0]), [0, 80]);
    expect(store().scene.lights![1]).toMatchObject({ position: [1, 3, 0], lookAt: [0, 0, 2] });
    expect(store().selection).toEqual({ kind: 'lightAim', index: 1 });
    expect(within(svg).getByTestId('light-aim-1')).toHaveAttribute('data-selected', 'true');
    expect(store().past).toHaveLength(2);
  });

  it('fit an area light’s corners and aim, and box-select it by its centre', () => {
    const points = scenePoints({ objects: [], lights: [{ type: 'area', position: [10, 3, 0], size: [4, 1], lookAt: [10, 0, 7] }] });
    expect(points).toContainEqual([10, 0, 7]);
    expect(Math.max(...points.map((p) => p[0]))).toBeCloseTo(12, 9);
    const t: ViewTransform = { zoom: 40, pan: [0, 0], width: 480, height: 320 };
    const found = itemsInRect({ objects: [], lights: [{ type: 'area', position: [0, 3, 0] }] }, 'top', t, worldToSvg('top', t, [-0.5, 0, -0.5]), worldToSvg('top', t, [0.5, 0, 0.5]));
    expect(found).toEqual([{ kind: 'light', index: 0 }]); // an area light hanging over the origin
  });
});
