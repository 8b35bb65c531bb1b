/** Image sizes: the presets offered, and a size kept at its aspect ratio. Pure. */

export interface ImageSize {
  width: number;
  height: number;
}

/** The sizes one picks most, in the editor's menu. */
export const SIZE_PRESETS: { label: string; size: ImageSize }[] = [
  { label: '640 × 480 (4:3)', size: { width: 640, height: 480 } },
  { label: '1280 × 720 (HD)', size: { width: 1280, height: 720 } },
  { label: '1920 × 1080 (Full HD)', size: { width: 1920, height: 1080 } },
  { label: '1024 × 1024 (square)', size: { width: 1024, height: 1024 } },
];

/** The largest side the server renders (the image fields' maximum). */
export const MAX_SIDE = 4096;

const side = (v: number) => Math.min(MAX_SIDE, Math.max(1, Math.round(v)));

/**
 * The size after one side is set: with the aspect locked the other side follows (rounded to a
 * whole pixel, kept within 1..4096), without it only that side changes.
 */
export function resize(current: ImageSize, changed: keyof ImageSize, value: number, locked: boolean): ImageSize {
  const next = { ...current, [changed]: side(value) };
  if (!locked) return next;
  const aspect = current.width / current.height;
  return changed === 'width' ? { ...next, height: side(next.width / aspect) } : { ...next, width: side(next.height * aspect) };
}

/** The preset a size is, or -1. */
export function presetIndex(size: ImageSize): number {
  return SIZE_PRESETS.findIndex((p) => p.size.width === size.width && p.size.height === size.height);
}
