import { useEffect, useRef, useState } from 'react';
import { meshCache } from '../hooks/useMeshes';
import { sceneToThree } from '../model/toThree';
import { selectDisplayScene, useSceneStore } from '../store/sceneStore';
import { PreviewEngine, type PreviewMode } from './previewEngine';

/**
 * The three.js preview. "Camera view" looks through the render camera (same position, target,
 * up, vertical fov, aspect = image width / height, letterboxed); "Orbit view" lets you look
 * around with the mouse and shows the render camera's frustum. Frames are drawn on demand: the
 * store is followed by a subscription, never by per-frame React state.
 */
export function Preview3D() {
  const host = useRef<HTMLDivElement>(null);
  const engine = useRef<PreviewEngine | null>(null);
  const [mode, setMode] = useState<PreviewMode>('camera');
  const [failure, setFailure] = useState<string | null>(null);

  useEffect(() => {
    const element = host.current;
    if (!element) return;
    let preview: PreviewEngine;
    try {
      preview = new PreviewEngine();
    } catch (error) {
      setFailure(error instanceof Error ? error.message : String(error));
      return;
    }
    engine.current = preview;
    element.appendChild(preview.canvas);
    const push = () => {
      const state = useSceneStore.getState();
      preview.update(sceneToThree(selectDisplayScene(state), state.selection, (mesh) => meshCache.get(mesh)));
    };
    push();
    const unsubscribe = useSceneStore.subscribe((state, old) => {
      if (state.scene !== old.scene || state.preview !== old.preview || state.selection !== old.selection) push();
    });
    // A mesh file that finishes loading appears without waiting for the next edit.
    const unsubscribeMeshes = meshCache.subscribe(push);
    const measure = () => preview.resize(element.clientWidth, element.clientHeight);
    measure();
    const observer = typeof ResizeObserver === 'undefined' ? null : new ResizeObserver(measure);
    observer?.observe(element);
    return () => {
      unsubscribe();
      unsubscribeMeshes();
      observer?.disconnect();
      preview.dispose();
      engine.current = null;
    };
  }, []);

  useEffect(() => engine.current?.setMode(mode), [mode]);

  return (
    <section className="preview3d" aria-label="3D preview">
      <header className="panel-header">
        <h2>3D preview</h2>
        <div className="segmented" role="group" aria-label="Preview camera">
          <button type="button" aria-pressed={mode === 'camera'} onClick={() => setMode('camera')} title="See exactly what the render camera frames">
            Camera view
          </button>
          <button type="button" aria-pressed={mode === 'orbit'} onClick={() => setMode('orbit')} title="Look around freely: drag to orbit, wheel to zoom, right-drag to pan">
            Orbit view
          </button>
        </div>
      </header>
      <div className="preview3d__viewport" ref={host} data-testid="preview-3d" data-mode={mode}>
        {failure && (
          <p className="preview3d__failure" role="note">
            The 3D preview needs WebGL, which this browser does not offer ({failure}). The top and side views and rendering still work.
          </p>
        )}
      </div>
    </section>
  );
}
