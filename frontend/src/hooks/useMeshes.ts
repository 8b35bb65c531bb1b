import { useCallback, useEffect, useSyncExternalStore } from 'react';
import { fetchMeshFile, type FetchFn } from '../api/client';
import { MeshCache, type MeshState } from '../model/meshCache';
import type { MeshObject, Scene } from '../model/types';
import { useSceneStore } from '../store/sceneStore';

/** The editor's one mesh cache (parsed inline meshes and loaded mesh files). */
export const meshCache = new MeshCache();

/** A number that changes (with a re-render) whenever a mesh file finishes loading. */
export function useMeshVersion(): number {
  return useSyncExternalStore(meshCache.subscribe, meshCache.version);
}

/** Looks up a mesh's triangles; a new function (and a re-render) whenever a mesh file finishes loading. */
export function useMeshLookup(): (mesh: MeshObject) => MeshState {
  const version = useMeshVersion();
  // `version` is not read inside, but it is what changes the answers.
  // eslint-disable-next-line react-hooks/exhaustive-deps -- see above
  return useCallback((mesh: MeshObject) => meshCache.get(mesh), [version]);
}

/** The `file` names of a scene's meshes, one per line (a string, so a selector result is stable). */
export function meshFileNames(scene: Scene): string {
  return scene.objects.flatMap((o) => (o.type === 'mesh' && o.file !== undefined && o.obj === undefined ? [o.file] : [])).join('\n');
}

/** Loads every mesh file the scene names from the server, once per file (call once, near the top). */
export function useMeshFiles(fetchFn?: FetchFn): void {
  const files = useSceneStore((s) => meshFileNames(s.scene));
  useEffect(() => {
    for (const file of files.split('\n')) if (file) meshCache.ensure(file, (f) => fetchMeshFile(f, fetchFn));
  }, [files, fetchFn]);
}
