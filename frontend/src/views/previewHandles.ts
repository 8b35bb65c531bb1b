/**
 * Direct manipulation in the 3D preview (no React): a click picks the object or light under the
 * pointer, and three.js TransformControls put move, rotate or scale handles on the selection. The
 * handles hold a stand-in (an Object3D at the object's anchor, with its rotation), never the drawn
 * mesh, which follows the scene on every change; each handle movement reports the stand-in's
 * pose, and the release reports the end of the drag (the store commits one history entry).
 */
import { Euler, Object3D, Raycaster, Vector2, type Camera, type Scene } from 'three';
import { TransformControls } from 'three/examples/jsm/controls/TransformControls.js';
import type { GizmoMode, GizmoPose } from '../model/gizmo';
import type { DragTarget } from '../model/selection';

/** How far (CSS pixels) a press may move and still be a click that selects. */
const CLICK_SLOP = 4;
const DEGREES = 180 / Math.PI;

export interface HandleCallbacks {
  /** A click picked something, or empty space (null); `adding` when Shift, Ctrl or Cmd was held. */
  onPick(target: DragTarget | null, adding: boolean): void;
  /** The handles moved the stand-in to a new pose (during a drag). */
  onPose(pose: GizmoPose): void;
  /** A handle drag ended. */
  onRelease(): void;
  /** The handles were drawn differently (a new frame is needed). */
  onChange(): void;
  /** True while a handle is dragged (the orbit camera keeps still meanwhile). */
  onDragging(dragging: boolean): void;
}

export class PreviewHandles {
  private readonly controls: TransformControls;
  private readonly stand = new Object3D();
  private readonly raycaster = new Raycaster();
  /** Where the left button went down; `moved` once the pointer went further than a click may. */
  private press: { x: number; y: number; moved: boolean } | null = null;
  private handled = false;

  constructor(
    private readonly canvas: HTMLCanvasElement,
    scene: Scene,
    camera: Camera,
    private readonly pickables: () => Object3D[],
    private readonly callbacks: HandleCallbacks,
  ) {
    this.controls = new TransformControls(camera, canvas);
    this.controls.setSize(0.9);
    scene.add(this.stand);
    scene.add(this.controls.getHelper());
    this.controls.addEventListener('change', () => callbacks.onChange());
    this.controls.addEventListener('objectChange', () => callbacks.onPose(this.pose()));
    this.controls.addEventListener('dragging-changed', (event) => {
      const dragging = Boolean((event as unknown as { value: boolean }).value);
      callbacks.onDragging(dragging);
      if (dragging) this.handled = true;
      else callbacks.onRelease();
    });
    canvas.addEventListener('pointerdown', this.onDown);
    canvas.addEventListener('pointermove', this.onMove);
    canvas.addEventListener('pointerup', this.onUp);
  }

  /** True while a handle is being dragged. */
  get dragging(): boolean {
    return this.controls.dragging;
  }

  /** What must not appear in reflections: the handles. */
  helpers(): Object3D[] {
    return [this.controls.getHelper()];
  }

  setCamera(camera: Camera): void {
    this.controls.camera = camera;
  }

  /**
   * Shows the handles of `mode` at `pose`, or hides them (null). Ignored during a drag: the
   * stand-in is then where the handles put it, and the next pose comes with the committed scene.
   */
  attach(pose: GizmoPose | null, mode: GizmoMode, modes: GizmoMode[]): void {
    if (this.controls.dragging) return;
    if (!pose || !modes.includes(mode)) {
      if (pose && modes.length > 0) mode = modes[0];
      else {
        this.controls.detach();
        return;
      }
    }
    this.stand.position.set(...pose.position);
    this.stand.rotation.set(pose.rotation[0] / DEGREES, pose.rotation[1] / DEGREES, pose.rotation[2] / DEGREES, 'XYZ');
    this.stand.scale.set(1, 1, 1);
    this.stand.updateMatrixWorld();
    this.controls.setMode(mode);
    // boxes and meshes scale and turn along their own axes; moving is along the world's
    this.controls.setSpace(mode === 'translate' ? 'world' : 'local');
    if (this.controls.object !== this.stand) this.controls.attach(this.stand);
  }

  dispose(): void {
    this.canvas.removeEventListener('pointerdown', this.onDown);
    this.canvas.removeEventListener('pointermove', this.onMove);
    this.canvas.removeEventListener('pointerup', this.onUp);
    this.controls.detach();
    this.controls.getHelper().removeFromParent();
    this.controls.dispose();
    this.stand.removeFromParent();
  }

  private pose(): GizmoPose {
    const r = new Euler().copy(this.stand.rotation);
    return {
      position: this.stand.position.toArray() as GizmoPose['position'],
      rotation: [r.x * DEGREES, r.y * DEGREES, r.z * DEGREES],
      scale: this.stand.scale.toArray() as GizmoPose['scale'],
    };
  }

  private readonly onDown = (event: PointerEvent) => {
    // TransformControls hears the press first: on a handle it is already dragging
    this.handled = this.controls.dragging;
    this.press = event.button === 0 ? { x: event.clientX, y: event.clientY, moved: false } : null;
  };

  // an orbit drag that comes back to where it started is still a drag, not a click
  private readonly onMove = (event: PointerEvent) => {
    if (this.press && Math.hypot(event.clientX - this.press.x, event.clientY - this.press.y) > CLICK_SLOP) this.press.moved = true;
  };

  private readonly onUp = (event: PointerEvent) => {
    const press = this.press;
    this.press = null;
    if (!press || this.handled || press.moved || Math.hypot(event.clientX - press.x, event.clientY - press.y) > CLICK_SLOP) return;
    this.callbacks.onPick(this.pick(event.clientX, event.clientY), event.shiftKey || event.ctrlKey || event.metaKey);
  };

  /** The object or light under a point of the canvas (client pixels), or null. */
  pick(clientX: number, clientY: number): DragTarget | null {
    const rect = this.canvas.getBoundingClientRect();
    const ndc = new Vector2(((clientX - rect.left) / rect.width) * 2 - 1, -((clientY - rect.top) / rect.height) * 2 + 1);
    this.raycaster.setFromCamera(ndc, this.controls.camera);
    for (const hit of this.raycaster.intersectObjects(this.pickables(), false)) {
      const target = hit.object.userData.target as DragTarget | undefined;
      if (target) return target;
    }
    return null;
  }
}
