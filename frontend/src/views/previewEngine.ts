/**
 * The imperative side of the 3D preview (no React): owns the WebGL renderer, the render camera
 * and an orbit camera, shows the scene's content ({@link PreviewContent}), and draws one frame
 * only when asked (scene change, resize, orbit movement).
 */
import { BasicShadowMap, Color, PerspectiveCamera, Scene, Vector3, WebGLRenderer } from 'three';
import { OrbitControls } from 'three/examples/jsm/controls/OrbitControls.js';
import { frameBall, type GizmoMode, type GizmoPose } from '../model/gizmo';
import type { Vec3 } from '../model/types';
import { applyRenderCamera, letterbox, type ThreeSceneDescriptor } from '../model/toThree';
import type { DrawProgress } from './firstDraw';
import { PreviewContent } from './previewContent';
import { PreviewHandles, type HandleCallbacks } from './previewHandles';
import { probeWebgl } from './webglSupport';

/**
 * What the engine draws: the scene through the render camera or the orbit camera, or (`overlay`)
 * only the handles, on a transparent canvas through the render camera, over the live ray-traced
 * image; its picking still finds the scene's objects (hidden, not removed).
 */
export type PreviewMode = 'camera' | 'orbit' | 'overlay';

/**
 * OrbitControls' speeds, below its defaults (1, 1, 1): with them a drag across the view turned it
 * by more than a full circle and one wheel notch zoomed by 5%, which users found hard to aim.
 */
export const ORBIT_SPEEDS = { rotateSpeed: 0.45, zoomSpeed: 0.5, panSpeed: 0.6 } as const;

export class PreviewEngine {
  readonly canvas: HTMLCanvasElement;
  private readonly renderer: WebGLRenderer;
  private readonly scene = new Scene();
  private readonly background = new Color();
  private readonly content = new PreviewContent(() => {
    this.stale = true;
    this.requestRender();
  });
  private readonly renderCamera = new PerspectiveCamera();
  private readonly orbitCamera = new PerspectiveCamera(50, 1, 0.01, 1e4);
  private readonly controls: OrbitControls;
  private mode: PreviewMode = 'camera';
  private orbitPlaced = false;
  private size = { width: 1, height: 1 };
  private last: ThreeSceneDescriptor | null = null;
  private frame = 0;
  /** The content changed since the shadow maps and reflections were last taken. */
  private stale = true;
  /** The last frame drew a large new mesh's first part: this one takes the shadows ({@link requestRender}). */
  private shadowsNext = false;
  private progress: DrawProgress | null = null;

  /** Told how much of a large mesh just added is drawn, and null once every one is whole. */
  onDrawProgress: (progress: DrawProgress | null) => void = () => {};
  private readonly handles: PreviewHandles;

  /** Throws when WebGL 2 is not available. */
  constructor(callbacks: Pick<HandleCallbacks, 'onPick' | 'onPose' | 'onRelease'> = { onPick: () => {}, onPose: () => {}, onRelease: () => {} }) {
    const support = probeWebgl();
    if (!support.webgl2) throw new Error('WebGL 2 is not available');
    // preserveDrawingBuffer: the picture can be read back (the browser test checks its shadows);
    // alpha: over the live image only the handles are opaque; no multisampling in software WebGL,
    // where it cost 0.12 s a frame on the 200,978-triangle mesh (docs/editor.md, the browser test)
    this.renderer = new WebGLRenderer({ antialias: !support.software, preserveDrawingBuffer: true, alpha: true });
    this.renderer.setPixelRatio(Math.min(2, globalThis.devicePixelRatio || 1));
    this.canvas = this.renderer.domElement;
    this.scene.add(this.content.root);
    this.scene.background = this.background;
    // The render has shadows: so does the preview. No made-up environment: mirrors, metals and
    // glass reflect the scene itself (ReflectionProbes) or nothing.
    // Shadow maps and reflections are taken again when the scene changes, not when only the view
    // moves (orbiting stays as cheap as before).
    this.renderer.shadowMap.enabled = true;
    // Hard-edged, as the engine's point lights cast them (and PCF point-light shadows came out
    // empty in Chromium's software WebGL, measured with three 0.187)
    this.renderer.shadowMap.type = BasicShadowMap;
    this.renderer.shadowMap.autoUpdate = false;
    this.controls = new OrbitControls(this.orbitCamera, this.canvas);
    this.controls.enabled = false;
    Object.assign(this.controls, ORBIT_SPEEDS);
    this.controls.addEventListener('change', () => this.requestRender());
    this.handles = new PreviewHandles(this.canvas, this.scene, this.renderCamera, () => this.content.pickables, {
      ...callbacks,
      onChange: () => this.requestRender(),
      onDragging: (dragging) => {
        this.controls.enabled = !dragging && this.mode === 'orbit';
      },
    });
  }

  /** Shows a scene's descriptor: what is already shown changes in place (see {@link PreviewContent}). */
  update(d: ThreeSceneDescriptor): void {
    this.last = d;
    this.content.update(d, this.mode === 'orbit');
    this.stale = true;
    this.background.set(d.background);
    applyRenderCamera(this.renderCamera, d.camera);
    this.orbitCamera.far = d.camera.far;
    this.orbitCamera.near = d.camera.near;
    this.layout();
  }

  /** Shows the handles of `mode` at `pose` on the selection, or none (null). */
  setHandles(pose: GizmoPose | null, mode: GizmoMode, modes: GizmoMode[]): void {
    this.handles.attach(pose, mode, modes);
    this.requestRender();
  }

  /** True while a handle is dragged. */
  get dragging(): boolean {
    return this.handles.dragging;
  }

  /** Turns the orbit camera on a ball (the selection's extent) so that it fills the view. */
  frameOn(center: Vec3, radius: number): void {
    const to = frameBall(center, radius, this.orbitCamera.fov, this.orbitCamera.position.toArray() as Vec3);
    this.orbitPlaced = true;
    this.orbitCamera.position.set(...to.position);
    this.controls.target.set(...to.target);
    this.orbitCamera.far = Math.max(this.orbitCamera.far, 10 * radius);
    this.controls.update();
    this.requestRender();
  }

  setMode(mode: PreviewMode): void {
    this.mode = mode;
    this.controls.enabled = mode === 'orbit';
    this.handles.setCamera(mode === 'orbit' ? this.orbitCamera : this.renderCamera);
    this.content.root.visible = mode !== 'overlay';
    this.scene.background = mode === 'overlay' ? null : this.background;
    if (mode === 'orbit' && !this.orbitPlaced) this.resetOrbit();
    if (this.last) this.update(this.last);
  }

  /** Where the orbit camera is, what it looks at and its up: a render camera that frames what it sees. */
  orbitView(): { position: Vec3; lookAt: Vec3; up: Vec3 } {
    return {
      position: this.orbitCamera.position.toArray() as Vec3,
      lookAt: this.controls.target.toArray() as Vec3,
      up: this.orbitCamera.up.toArray() as Vec3,
    };
  }

  /** Where the camera shown looks (`forward`) and its right, in world coordinates (the arrow keys' axes). */
  viewAxes(): { forward: Vec3; right: Vec3 } {
    const camera = this.mode === 'orbit' ? this.orbitCamera : this.renderCamera;
    camera.updateMatrixWorld();
    const forward = camera.getWorldDirection(new Vector3());
    const right = new Vector3().crossVectors(forward, camera.up).normalize();
    return { forward: forward.toArray() as Vec3, right: right.toArray() as Vec3 };
  }

  /** Puts the orbit camera back where the render camera is, looking at its target. */
  resetOrbit(): void {
    if (!this.last) return;
    this.orbitPlaced = true;
    this.orbitCamera.position.copy(this.renderCamera.position);
    this.orbitCamera.up.copy(this.renderCamera.up);
    this.controls.target.set(...this.last.camera.lookAt);
    this.controls.update();
    this.requestRender();
  }

  /** The container's size; in camera and overlay mode the canvas is letterboxed to the image aspect. */
  resize(width: number, height: number): void {
    this.size = { width: Math.max(1, width), height: Math.max(1, height) };
    this.layout();
  }

  requestRender(): void {
    if (this.frame) return;
    this.frame = requestAnimationFrame(() => {
      this.frame = 0;
      // A large new mesh comes in a step a frame: none of it (its shaders set up, its buffers
      // uploaded), its first part (the shaders compiled in drawing it), the shadow maps of that part
      // (theirs compiled), its other parts, then the shadow maps and reflections of the whole.
      // Software WebGL holds the page for a whole frame, shader compiles included, and frames that
      // both grew and took the shadows were the longest (docs/editor.md)
      const shadowsNow = this.shadowsNext;
      this.shadowsNext = false;
      if (this.content.growing && !shadowsNow) {
        this.shadowsNext = this.content.drawNextPart();
        this.stale = true;
      } else if (this.stale && this.mode !== 'overlay') {
        this.stale = false;
        this.renderer.shadowMap.needsUpdate = true;
        this.content.takeReflections(this.renderer, this.scene, this.handles.helpers());
      }
      this.renderer.render(this.scene, this.mode === 'orbit' ? this.orbitCamera : this.renderCamera);
      this.tellProgress();
      if (this.content.growing || (this.stale && this.mode !== 'overlay')) this.requestRender();
    });
  }

  /** Tells {@link onDrawProgress} when the share drawn of the large new meshes changed. */
  private tellProgress(): void {
    const now = this.content.drawProgress();
    if (now?.drawn === this.progress?.drawn && now?.total === this.progress?.total) return;
    this.progress = now;
    this.onDrawProgress(now);
  }

  dispose(): void {
    cancelAnimationFrame(this.frame);
    this.handles.dispose();
    this.content.dispose();
    this.controls.dispose();
    this.renderer.dispose();
    this.renderer.forceContextLoss();
    this.canvas.remove();
  }

  private layout(): void {
    const { width, height } = this.size;
    const box = this.mode !== 'orbit' && this.last ? letterbox(width, height, this.last.camera.aspect) : { width, height, left: 0, top: 0 };
    this.renderer.setSize(Math.max(1, Math.floor(box.width)), Math.max(1, Math.floor(box.height)));
    this.canvas.style.left = `${box.left}px`;
    this.canvas.style.top = `${box.top}px`;
    this.orbitCamera.aspect = box.width / Math.max(1, box.height);
    this.orbitCamera.updateProjectionMatrix();
    this.requestRender();
  }
}
