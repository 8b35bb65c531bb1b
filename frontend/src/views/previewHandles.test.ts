import { Mesh, MeshBasicMaterial, PerspectiveCamera, PlaneGeometry, Scene } from 'three';
import { afterEach, describe, expect, it, vi } from 'vitest';
import type { DragTarget } from '../model/selection';
import { PreviewHandles } from './previewHandles';

/** A 200x100 canvas looking down -z at a floor-like square that fills the view, picked as object 0. */
function setup() {
  const canvas = document.createElement('canvas');
  document.body.appendChild(canvas);
  vi.spyOn(canvas, 'getBoundingClientRect').mockReturnValue({ left: 0, top: 0, width: 200, height: 100, right: 200, bottom: 100, x: 0, y: 0, toJSON: () => ({}) });
  const camera = new PerspectiveCamera(50, 2, 0.1, 100);
  camera.updateMatrixWorld();
  const floor = new Mesh(new PlaneGeometry(100, 100), new MeshBasicMaterial());
  floor.position.set(0, 0, -5);
  floor.userData.target = { kind: 'object', index: 0 } satisfies DragTarget;
  floor.updateMatrixWorld();
  const picks: (DragTarget | null)[] = [];
  const handles = new PreviewHandles(canvas, new Scene(), camera, () => [floor], {
    onPick: (target) => picks.push(target),
    onPose: () => {},
    onRelease: () => {},
    onChange: () => {},
    onDragging: () => {},
  });
  const pointer = (type: string, x: number, y: number) => canvas.dispatchEvent(new PointerEvent(type, { clientX: x, clientY: y, button: 0, pointerId: 1, bubbles: true }));
  return { handles, picks, pointer, canvas };
}

describe('PreviewHandles', () => {
  afterEach(() => {
    vi.restoreAllMocks();
    document.body.innerHTML = '';
  });

  it('selects what a click without a drag is on, through its camera', () => {
    const { picks, pointer, handles } = setup();
    pointer('pointerdown', 100, 50);
    pointer('pointerup', 101, 51);
    expect(picks).toEqual([{ kind: 'object', index: 0 }]);
    expect(handles.pick(100, 50)).toEqual({ kind: 'object', index: 0 });
  });

  it('does not select when an orbit drag starts on an object, even one that ends where it started', () => {
    const { picks, pointer } = setup();
    pointer('pointerdown', 100, 50);
    pointer('pointermove', 140, 50);
    pointer('pointerup', 140, 50);
    pointer('pointerdown', 100, 50);
    pointer('pointermove', 160, 80);
    pointer('pointermove', 101, 50);
    pointer('pointerup', 100, 50);
    expect(picks).toEqual([]);
  });
});
