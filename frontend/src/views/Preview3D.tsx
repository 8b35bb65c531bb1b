import { useEffect, useRef, useState } from 'react';
import { meshCache } from '../hooks/useMeshes';
import type { SocketFactory } from '../live/liveSession';
import { RayTracedView } from '../live/RayTracedView';
import { DrawProgressNote } from './DrawProgressNote';
import type { DrawProgress } from './firstDraw';
import { HandleModes } from './HandleModes';
import { sceneToThree } from '../model/toThree';
import { selectDisplayScene, useSceneStore } from '../store/sceneStore';
import { handleCallbacks, handlesFor, selectionBall } from './previewSelection';
import { PreviewEngine, type PreviewMode } from './previewEngine';
import { nudgeSelection, nudgeStep } from './viewNudge';

/** What the preview shows: one of the three.js cameras, or the server's ray-traced frames. */
export type PreviewView = PreviewMode | 'raytraced';

/** Props of {@link Preview3D}. */
export interface Preview3DProps {
  /** False while the panel is hidden behind another tab: the ray-traced view then closes its connection. */
  shown?: boolean;
  /** Receives the field errors of a scene the ray-traced view's server refused (`{}` once it renders). */
  onFieldErrors?: (errors: Record<string, string>) => void;
  /** Opens the ray-traced view's socket; `new WebSocket(url)` by default, a fake in tests. */
  socketFactory?: SocketFactory;
}

/**
 * The three.js preview. "Camera view" looks through the render camera (same position, target,
 * up, vertical fov, aspect = image width / height, letterboxed); "Orbit view" lets you look
 * around with the mouse and shows the render camera's frustum. Frames are drawn on demand: the
 * store is followed by a subscription, never by per-frame React state. "Ray traced" shows the
 * server's live render instead (its socket open only while that view is shown), with the same
 * picking and handles over it (through the render camera, as the Camera view). A click selects
 * what is under it; the selection carries move, rotate or scale handles (W, E, R), one drag being
 * one undo step that the live image follows; F frames the selection (in the orbit view).
 */
export function Preview3D({ shown = true, onFieldErrors, socketFactory }: Preview3DProps) {
  const host = useRef<HTMLDivElement>(null);
  const engine = useRef<PreviewEngine | null>(null);
  const [view, setView] = useState<PreviewView>('camera');
  const [failure, setFailure] = useState<string | null>(null);
  const [drawing, setDrawing] = useState<DrawProgress | null>(null);
  const viewRef = useRef(view);
  const push = useRef(() => {});

  useEffect(() => {
    const element = host.current;
    if (!element) return;
    let preview: PreviewEngine;
    try {
      preview = new PreviewEngine(handleCallbacks);
    } catch (error) {
      setFailure(error instanceof Error ? error.message : String(error));
      return;
    }
    engine.current = preview;
    preview.onDrawProgress = setDrawing;
    element.appendChild(preview.canvas);
    // focusable, so that the arrow keys move the selection here as in the plan views
    preview.canvas.tabIndex = 0;
    preview.canvas.setAttribute('role', 'img');
    preview.canvas.setAttribute('aria-label', 'The scene in 3D: click to select, arrow keys move the selection (Shift+Up and Down: up and down)');
    const onKeyDown = (event: KeyboardEvent) => {
      const { forward, right } = preview.viewAxes();
      const by = nudgeStep(event.key, event.shiftKey, forward, right, useSceneStore.getState().gridSize);
      if (by && !event.ctrlKey && !event.metaKey && !event.altKey && nudgeSelection(by)) event.preventDefault();
    };
    preview.canvas.addEventListener('keydown', onKeyDown);
    const update = () => {
      const state = useSceneStore.getState();
      const scene = selectDisplayScene(state);
      preview.update(sceneToThree(scene, state.selection, (mesh) => meshCache.get(mesh), state.selectedItems));
      const handles = handlesFor(scene, state.selection);
      preview.setHandles(handles?.pose ?? null, state.gizmo, handles?.modes ?? []);
    };
    push.current = update;
    update();
    const unsubscribe = useSceneStore.subscribe((state, old) => {
      if (state.scene !== old.scene || state.preview !== old.preview || state.selection !== old.selection || state.selectedItems !== old.selectedItems || state.gizmo !== old.gizmo) update();
      if (state.frameRequest !== old.frameRequest) {
        const ball = selectionBall(state.scene, state.selection, (mesh) => meshCache.get(mesh));
        if (viewRef.current !== 'orbit') setView('orbit');
        preview.frameOn(ball.center, ball.radius);
      }
    });
    // A mesh file that finishes loading appears without waiting for the next edit.
    const unsubscribeMeshes = meshCache.subscribe(update);
    const measure = () => preview.resize(element.clientWidth, element.clientHeight);
    measure();
    const observer = typeof ResizeObserver === 'undefined' ? null : new ResizeObserver(measure);
    observer?.observe(element);
    return () => {
      unsubscribe();
      unsubscribeMeshes();
      observer?.disconnect();
      preview.canvas.removeEventListener('keydown', onKeyDown);
      preview.dispose();
      engine.current = null;
    };
  }, []);

  useEffect(() => {
    viewRef.current = view;
    // over the live image, the engine draws only the handles, through the render camera
    engine.current?.setMode(view === 'raytraced' ? 'overlay' : view);
  }, [view]);

  const viewButton = (id: PreviewView, label: string, title: string) => (
    <button type="button" aria-pressed={view === id} onClick={() => setView(id)} title={title}>
      {label}
    </button>
  );

  return (
    <section className="preview3d" aria-label="3D preview">
      <header className="panel-header">
        <h2>3D preview</h2>
        <HandleModes />
        <div className="segmented" role="group" aria-label="Preview camera">
          {viewButton('camera', 'Camera view', 'See exactly what the render camera frames')}
          {viewButton('orbit', 'Orbit view', 'Look around freely: drag to orbit, wheel to zoom, right-drag to pan')}
          {viewButton('raytraced', 'Ray traced', 'See the server’s render, refined live as you edit')}
        </div>
        {view === 'orbit' && (
          <>
            <button
              type="button"
              className="small"
              onClick={() => {
                const seen = engine.current?.orbitView();
                if (seen) useSceneStore.getState().setCamera(seen);
              }}
              title="Make the render camera look as this view does (position, target and up; one undo step)"
            >
              Camera from this view
            </button>
            <button type="button" className="small" onClick={() => engine.current?.resetOrbit()} title="Look through the render camera again">
              Reset view
            </button>
          </>
        )}
      </header>
      <div className="preview3d__stage">
        {view === 'raytraced' && shown && <RayTracedView onFieldErrors={onFieldErrors} socketFactory={socketFactory} />}
        <div className={view === 'raytraced' ? 'preview3d__viewport is-overlay' : 'preview3d__viewport'} ref={host} data-testid="preview-3d" data-mode={view}>
          {view !== 'raytraced' && <DrawProgressNote progress={drawing} />}
          {failure && view !== 'raytraced' && (
            <p className="preview3d__failure" role="note">
              The 3D preview needs WebGL, which this browser does not offer ({failure}). The top and side views and rendering still work.
            </p>
          )}
        </div>
      </div>
    </section>
  );
}
