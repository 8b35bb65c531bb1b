import { useEffect, useRef } from 'react';
import { useMeshVersion, meshCache } from '../hooks/useMeshes';
import { fitViews, scenePoints } from '../model/bounds';
import type { ViewKind } from '../model/projection';
import { useSceneStore, type ViewState } from '../store/sceneStore';

/**
 * Zooms a plan view to the whole scene when one arrives (a new fit request), again once the view
 * has its real size, and again when a mesh file arrives after the fit (its bounds were not known
 * yet) as long as nobody has moved the view since.
 */
export function useFitView(kind: ViewKind, size: { width: number; height: number; measured: boolean }): void {
  const fitRequest = useSceneStore((s) => s.fitRequest);
  const meshVersion = useMeshVersion();
  const fitted = useRef<{ request: number; measured: boolean; meshes: number; view: ViewState | null }>({ request: 0, measured: false, meshes: 0, view: null });
  useEffect(() => {
    const state = useSceneStore.getState();
    const last = fitted.current;
    const fresh = last.request !== fitRequest || (!last.measured && size.measured);
    const meshesArrived = last.meshes !== meshVersion && last.view !== null && state.views[kind] === last.view;
    if (!fresh && !meshesArrived) {
      last.meshes = meshVersion;
      return;
    }
    const view = fitViews(scenePoints(state.scene, (mesh) => meshCache.get(mesh)), size.width, size.height)[kind];
    fitted.current = { request: fitRequest, measured: size.measured, meshes: meshVersion, view };
    state.setView(kind, view);
  }, [fitRequest, size, kind, meshVersion]);
}
