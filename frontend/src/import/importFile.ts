/**
 * One imported file, start to end: planned by its extension, hashed (in a worker), read where the
 * editor must read it (an OBJ in slices, a glTF through three.js), uploaded only if the server
 * lacks it, kept in this browser by id, and put into the scene by id: an OBJ as a `mesh`, a glTF
 * as a `gltf` object, an image as the selected object's texture. Each phase reports its progress;
 * every problem rejects with an {@link ImportProblem} whose message says what and why.
 */
import { ApiError } from '../api/client';
import type { AssetInfo } from '../api/assets';
import { planImport, type ImportPlan } from '../model/importFiles';
import { meshBounds, scaleToFit, type Bounds, type ParsedObj } from '../model/obj';
import type { Selection } from '../model/selection';
import type { Material, Scene } from '../model/types';
import type { StoredAsset } from '../store/editorDb';

/** What the import is doing now, with the fraction done when known. */
export type ImportPhase = 'hashing' | 'reading' | 'uploading';

/** A problem with one file, said for people. */
export class ImportProblem extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'ImportProblem';
  }
}

/** What an import needs from the world (the browser's in the editor, fakes in tests). */
export interface ImportDeps {
  hash(file: Blob, onProgress: (fraction: number) => void): Promise<string>;
  exists(id: string): Promise<boolean>;
  upload(file: Blob, mediaType: string, onProgress: (fraction: number) => void): Promise<AssetInfo>;
  keep(asset: StoredAsset): Promise<void>;
  readObj(text: string, onProgress: (fraction: number) => void): Promise<ParsedObj>;
  /** Reads a glTF model's bounds (rejecting with what is wrong with it). */
  readGltf(bytes: ArrayBuffer): Promise<Bounds>;
}

/** What an import changes in the editor (the store's actions). */
export interface ImportTarget {
  scene(): Scene;
  selection(): Selection;
  addModel(model: Scene['objects'][number] & { type: 'mesh' | 'gltf' }, bounds?: Bounds): void;
  setMaterial(index: number, material: Material): void;
  /** Keeps an OBJ just read, so the views do not read it again. */
  putMesh(id: string, mesh: ParsedObj): void;
  /** Gives the mesh at `index` the triangles of the OBJ asset `id`. */
  setMeshAsset(index: number, id: string): void;
}

/** What an import is for: by default it adds a model or textures the selection. */
export interface ImportOptions {
  /** An OBJ replaces the triangles of the mesh at this index instead of adding one. */
  replaceMesh?: number;
}

/** Says what an import is doing. */
export type ProgressFn = (phase: ImportPhase, fraction: number) => void;

/** The object an image would texture, or the sentence saying why there is none. */
export function textureTarget(scene: Scene, selection: Selection, name: string): number | string {
  if (selection?.kind !== 'object') return `Cannot use ${name} as a texture: select the object whose material it should cover first, then drop or import the image again.`;
  const object = scene.objects[selection.index];
  if (object?.type === 'gltf') return `Cannot use ${name} as a texture: a glTF model brings its own materials. Select a sphere, box, plane or mesh.`;
  return selection.index;
}

export async function importFile(file: File, deps: ImportDeps, target: ImportTarget, progress: ProgressFn, options: ImportOptions = {}): Promise<string> {
  const plan = planImport(file.name, file.size);
  if ('problem' in plan) throw new ImportProblem(plan.problem);
  if (options.replaceMesh !== undefined && plan.kind !== 'obj') throw new ImportProblem(`Cannot use ${file.name} as a mesh's triangles: choose a Wavefront .obj file.`);
  const textured = plan.kind === 'image' ? textureTarget(target.scene(), target.selection(), file.name) : -1;
  if (typeof textured === 'string') throw new ImportProblem(textured);

  progress('hashing', 0);
  const id = await deps.hash(file, (f) => progress('hashing', f));
  // the editor reads a model itself (an image only the preview decodes, from the kept file)
  const bytes = plan.kind === 'image' ? null : await file.arrayBuffer();
  let parsed: ParsedObj | null = null;
  let bounds: Bounds | undefined;
  if (plan.kind === 'obj') {
    progress('reading', 0);
    try {
      parsed = await deps.readObj(new TextDecoder().decode(bytes!), (f) => progress('reading', f));
    } catch (error) {
      throw new ImportProblem(`Cannot import ${file.name}: it is not a usable OBJ mesh (${messageOf(error)}).`);
    }
    if (parsed.triangleCount === 0) throw new ImportProblem(`Cannot import ${file.name}: it has no faces.`);
    bounds = meshBounds({}, parsed);
  } else if (plan.kind === 'gltf') {
    progress('reading', 0);
    try {
      bounds = await deps.readGltf(bytes!);
    } catch (error) {
      throw new ImportProblem(`Cannot import ${file.name}: ${messageOf(error)}.`);
    }
  }
  await sendToServer(file, id, plan, deps, progress);
  // the File itself: the browser keeps it without copying its bytes on this thread
  await deps.keep({ id, mediaType: plan.mediaType, bytes: file });
  if (options.replaceMesh !== undefined) {
    target.putMesh(id, parsed!);
    target.setMeshAsset(options.replaceMesh, id);
    return `${file.name}: ${parsed!.triangleCount.toLocaleString('en')} triangles now make the mesh.`;
  }
  return place(file.name, id, plan, parsed, bounds, textured, target);
}

/** Uploads the bytes unless the server has them already (HEAD); a refusal becomes an ImportProblem. */
async function sendToServer(file: File, id: string, plan: ImportPlan, deps: ImportDeps, progress: ProgressFn): Promise<void> {
  try {
    if (await deps.exists(id)) return;
    progress('uploading', 0);
    const answer = await deps.upload(file, plan.mediaType, (f) => progress('uploading', f));
    if (answer.id !== id) throw new ImportProblem(`Cannot import ${file.name}: the server named it ${answer.id}, not ${id} as this editor hashed it.`);
  } catch (error) {
    if (error instanceof ImportProblem) throw error;
    const fields = error instanceof ApiError && error.errors.length > 0 ? ` ${error.errors.map((e) => `${e.field}: ${e.message}`).join('; ')}` : '';
    throw new ImportProblem(`Cannot import ${file.name}: the server refused it (${messageOf(error)}).${fields}`);
  }
}

/** A file's name without its folder and extension (`teapot` of `models/teapot.obj`), the new object's name. */
export function fileStem(fileName: string): string {
  const base = fileName.replace(/^.*[\\/]/, '');
  const dot = base.lastIndexOf('.');
  return (dot > 0 ? base.slice(0, dot) : base).slice(0, 200);
}

function place(name: string, id: string, plan: ImportPlan, parsed: ParsedObj | null, bounds: Bounds | undefined, textured: number, target: ImportTarget): string {
  if (plan.kind === 'obj') {
    target.putMesh(id, parsed!);
    target.addModel({ type: 'mesh', name: fileStem(name), asset: id, scale: scaleToFit(parsed!), material: { type: 'plastic', color: '#4f8fd6' } }, bounds);
    return `${name}: ${parsed!.triangleCount.toLocaleString('en')} triangles added as a mesh.`;
  }
  if (plan.kind === 'gltf') {
    target.addModel({ type: 'gltf', name: fileStem(name), asset: id }, bounds);
    return `${name}: added as a glTF model.`;
  }
  const object = target.scene().objects[textured];
  const material: Material = object.material ?? { type: 'chalk' };
  target.setMaterial(textured, { ...material, texture: { type: 'image', asset: id, scale: [1, 1] } });
  return `${name}: now the texture of the selected object.`;
}

function messageOf(error: unknown): string {
  return error instanceof Error ? error.message : String(error);
}
