/**
 * glTF models for the preview, read by three.js's GLTFLoader from an asset's bytes (a `.glb`, or a
 * `.gltf` with its buffers and images embedded), each once per asset id. When a model is read,
 * its bounding box goes to the mesh cache, so the plan views, picking and framing know its extent;
 * when it cannot be, the cache holds the reason, which the views and the outline show.
 */
import { Box3, type Group } from 'three';
import { GLTFLoader } from 'three/examples/jsm/loaders/GLTFLoader.js';
import { boxMesh, type Bounds } from '../model/obj';
import type { MeshCache } from '../model/meshCache';

/** Reads a glTF model; rejects with an Error saying what is wrong with it. */
export async function parseGltf(bytes: ArrayBuffer): Promise<Group> {
  try {
    const gltf = await new GLTFLoader().parseAsync(bytes, '');
    return gltf.scene;
  } catch (error) {
    throw new Error(`not a glTF 2.0 model this editor can read (${error instanceof Error ? error.message : String(error)})`);
  }
}

/** The model's bounding box in its own coordinates (a point at the origin for an empty model). */
export function modelBounds(model: Group): Bounds {
  const box = new Box3().setFromObject(model);
  if (box.isEmpty()) return { min: [0, 0, 0], max: [0, 0, 0] };
  return { min: box.min.toArray(), max: box.max.toArray() };
}

const models = new Map<string, Group>();

/** The model of an asset, once read ({@link ensureModel}); undefined before. */
export function gltfModel(id: string): Group | undefined {
  return models.get(id);
}

/** Reads the asset's model unless it is read or on its way, and tells the mesh cache its box (or what is wrong). */
export function ensureModel(id: string, cache: MeshCache, loadBytes: (id: string) => Promise<ArrayBuffer>): void {
  if (cache.hasModel(id)) return;
  cache.setModel(id, { status: 'loading' });
  loadBytes(id)
    .then(parseGltf)
    .then(
      (model) => {
        models.set(id, model);
        cache.setModel(id, { status: 'ready', mesh: boxMesh(modelBounds(model)) });
      },
      (error: unknown) => cache.setModel(id, { status: 'error', message: error instanceof Error ? error.message : String(error) }),
    );
}
