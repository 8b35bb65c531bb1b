import { useCallback } from 'react';
import { assetExists, progressFetch, uploadAsset } from '../api/assets';
import { authorizedFetch } from '../api/auth';
import type { FetchFn } from '../api/client';
import { meshCache } from '../hooks/useMeshes';
import { parseObjInChunks } from '../model/obj';
import { keepAsset } from '../store/autosave';
import { useSceneStore } from '../store/sceneStore';
import { hashFile } from './hashFile';
import { importFile, ImportProblem, type ImportDeps, type ImportOptions, type ImportTarget } from './importFile';
import { useImportStore } from './importStore';

/** The browser's side of an import; `fetchFn` for every request (uploads report progress with the browser's own). */
function browserDeps(fetchFn: FetchFn | undefined): ImportDeps {
  return {
    hash: hashFile,
    exists: (id) => assetExists(id, fetchFn),
    upload: (file, mediaType, onProgress) => uploadAsset(file, mediaType, fetchFn ?? authorizedFetch(progressFetch(onProgress))),
    keep: keepAsset,
    readObj: (text, onProgress) => parseObjInChunks(text, { onProgress }),
    readGltf: async (bytes) => {
      const { parseGltf, modelBounds } = await import('../views/gltfModels');
      return modelBounds(await parseGltf(bytes));
    },
  };
}

const target: ImportTarget = {
  scene: () => useSceneStore.getState().scene,
  selection: () => useSceneStore.getState().selection,
  addModel: (model, bounds) => useSceneStore.getState().addModel(model, bounds),
  setMaterial: (index, material) => useSceneStore.getState().setMaterial(index, material),
  putMesh: (id, mesh) => meshCache.putAsset(id, mesh),
  setMeshAsset: (index, id) => useSceneStore.getState().setMeshAsset(index, id),
};

/**
 * Imports files one after another (the toolbar's + Import and + Mesh, a drop on the stage), the
 * progress in {@link useImportStore}; each problem goes to `onProblem`, none is swallowed.
 */
export function useImport(fetchFn: FetchFn | undefined, onProblem: (message: string) => void): (files: File[], options?: ImportOptions) => Promise<void> {
  return useCallback(
    async (files: File[], options?: ImportOptions) => {
      const deps = browserDeps(fetchFn);
      const problems: string[] = [];
      useImportStore.setState({ done: null });
      for (const [i, file] of files.entries()) {
        useImportStore.setState({ current: { name: file.name, phase: 'hashing', fraction: 0 }, waiting: files.length - i - 1 });
        try {
          const done = await importFile(file, deps, target, (phase, fraction) => useImportStore.setState({ current: { name: file.name, phase, fraction } }), options);
          useImportStore.setState({ done });
        } catch (error) {
          problems.push(error instanceof ImportProblem ? error.message : `Cannot import ${file.name}: ${error instanceof Error ? error.message : String(error)}`);
        }
      }
      useImportStore.setState({ current: null, waiting: 0 });
      if (problems.length > 0) onProblem(problems.join('\n'));
    },
    [fetchFn, onProblem],
  );
}
