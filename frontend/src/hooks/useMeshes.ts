import { useCallback, useEffect, useSyncExternalStore } from 'react';
import { assetExists, fetchAsset, uploadAsset } from '../api/assets';
import { fetchMeshFile, type FetchFn } from '../api/client';
import { keepAsset, keptAsset } from '../store/autosave';
import { assetBuffer, assetIdsOf } from '../store/editorDb';
import { MeshCache, type MeshState, type ModelRef } from '../model/meshCache';
import type { Scene } from '../model/types';
import { useSceneStore } from '../store/sceneStore';

/** The editor's one mesh cache (parsed inline meshes and loaded mesh files). */
export const meshCache = new MeshCache();

/** A number that changes (with a re-render) whenever a mesh file finishes loading. */
export function useMeshVersion(): number {
  return useSyncExternalStore(meshCache.subscribe, meshCache.version);
}

/** Looks up a mesh's triangles; a new function (and a re-render) whenever a mesh file finishes loading. */
export function useMeshLookup(): (mesh: ModelRef) => MeshState {
  const version = useMeshVersion();
  // `version` is not read inside, but it is what changes the answers.
  // eslint-disable-next-line react-hooks/exhaustive-deps -- see above
  return useCallback((mesh: ModelRef) => meshCache.get(mesh), [version]);
}

/** The `file` names of a scene's meshes, one per line (a string, so a selector result is stable). */
export function meshFileNames(scene: Scene): string {
  return scene.objects.flatMap((o) => (o.type === 'mesh' && o.file !== undefined && o.obj === undefined ? [o.file] : [])).join('\n');
}

/** The asset ids of a scene's meshes and glTF models, `mesh:ID` or `gltf:ID`, one per line (a stable selector result). */
export function modelAssets(scene: Scene): string {
  return scene.objects.flatMap((o) => (o.type === 'mesh' && o.asset !== undefined ? [`mesh:${o.asset}`] : o.type === 'gltf' ? [`gltf:${o.asset}`] : [])).join('\n');
}

/** An asset's bytes: as this browser keeps them, else from the server (and then kept). */
export async function loadAssetBytes(id: string, fetchFn?: FetchFn): Promise<ArrayBuffer> {
  const kept = await keptAsset(id);
  if (kept) return assetBuffer(kept);
  const blob = await fetchAsset(id, fetchFn);
  const bytes = await blob.arrayBuffer();
  void keepAsset({ id, mediaType: blob.type || 'application/octet-stream', bytes });
  return bytes;
}

/**
 * Loads every mesh file, mesh asset and glTF model the scene names, once each (call once, near
 * the top): files and assets from the server, or assets from what this browser keeps.
 */
export function useMeshFiles(fetchFn?: FetchFn): void {
  const files = useSceneStore((s) => meshFileNames(s.scene));
  const assets = useSceneStore((s) => modelAssets(s.scene));
  useEffect(() => {
    for (const file of files.split('\n')) if (file) meshCache.ensure(file, (f) => fetchMeshFile(f, fetchFn));
  }, [files, fetchFn]);
  useEffect(() => {
    for (const line of assets.split('\n')) {
      const [kind, id] = line.split(':');
      if (kind === 'mesh') meshCache.ensureAsset(id, async (a) => new TextDecoder().decode(await loadAssetBytes(a, fetchFn)));
      // three.js's loaders come with the preview's chunk
      if (kind === 'gltf' && !meshCache.hasModel(id)) void import('../views/gltfModels').then((m) => m.ensureModel(id, meshCache, (a) => loadAssetBytes(a, fetchFn)));
    }
  }, [assets, fetchFn]);
}

const offered = new Set<string>();

/**
 * Gives the server back the assets this browser keeps and the server has lost (a restart empties
 * its memory), once per id and page, so renders and the live view find every asset the scene names.
 */
export function useAssetsOnServer(fetchFn?: FetchFn): void {
  const ids = useSceneStore((s) => assetIdsOf(s.scene).join('\n'));
  useEffect(() => {
    for (const id of ids.split('\n')) {
      if (!id || offered.has(id)) continue;
      offered.add(id);
      void (async () => {
        const kept = await keptAsset(id);
        if (kept && !(await assetExists(id, fetchFn))) await uploadAsset(new Blob([kept.bytes]), kept.mediaType, fetchFn);
      })().catch(() => offered.delete(id)); // tried again on the next change of the scene's assets
    }
  }, [ids, fetchFn]);
}
