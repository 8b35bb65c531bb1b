/**
 * Which files the editor imports and as what (pure): `.obj` a mesh, `.glb`/`.gltf` a glTF model,
 * `.png`/`.jpg` an image texture, each with the media type the server's `POST /api/assets` takes.
 * Anything else, or a file too large to read, is refused with a sentence saying why.
 */

/** What an imported file becomes in the scene. */
export type ImportKind = 'obj' | 'gltf' | 'image';

export interface ImportPlan {
  kind: ImportKind;
  /** The `Content-Type` of the upload. */
  mediaType: 'model/obj' | 'model/gltf-binary' | 'model/gltf+json' | 'image/png' | 'image/jpeg';
}

/**
 * The largest file the editor reads (it holds the bytes in memory to hash them). The server has
 * its own limit (`studio.assets.max-bytes`, 16 MB by default) and answers 413 above it.
 */
export const MAX_IMPORT_BYTES = 256 * 1024 * 1024;

const BY_EXTENSION: Record<string, ImportPlan> = {
  obj: { kind: 'obj', mediaType: 'model/obj' },
  glb: { kind: 'gltf', mediaType: 'model/gltf-binary' },
  gltf: { kind: 'gltf', mediaType: 'model/gltf+json' },
  png: { kind: 'image', mediaType: 'image/png' },
  jpg: { kind: 'image', mediaType: 'image/jpeg' },
  jpeg: { kind: 'image', mediaType: 'image/jpeg' },
};

/** The extensions the picker offers. */
export const IMPORT_ACCEPT = '.obj,.glb,.gltf,.png,.jpg,.jpeg';

/** How a file of this name and size is imported, or why it cannot be. */
export function planImport(name: string, bytes: number): ImportPlan | { problem: string } {
  const dot = name.lastIndexOf('.');
  const extension = dot < 0 ? '' : name.slice(dot + 1).toLowerCase();
  const plan = BY_EXTENSION[extension];
  if (!plan) return { problem: `Cannot import ${name}: only .obj, .glb, .gltf, .png and .jpg files can be imported.` };
  if (bytes === 0) return { problem: `Cannot import ${name}: the file is empty.` };
  if (bytes > MAX_IMPORT_BYTES) return { problem: `Cannot import ${name}: it is ${formatBytes(bytes)}, more than the ${formatBytes(MAX_IMPORT_BYTES)} the editor reads.` };
  return plan;
}

/** 1536 → "1.5 KB", 16777216 → "16 MB". */
export function formatBytes(bytes: number): string {
  if (bytes < 1024) return `${bytes} bytes`;
  const units = ['KB', 'MB', 'GB'];
  let value = bytes / 1024;
  let unit = 0;
  while (value >= 1024 && unit < units.length - 1) {
    value /= 1024;
    unit++;
  }
  return `${Number(value.toPrecision(value < 10 ? 2 : 3))} ${units[unit]}`;
}
