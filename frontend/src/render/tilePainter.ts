/**
 * Painting finished tiles onto the preview canvas. Pure DOM, no React: tiles go straight to
 * the canvas and never through component state.
 */
import type { JobTile } from '../api/jobs';

/** A decoded tile, ready for `drawImage`; `close` frees an ImageBitmap's memory. */
export type DecodedTile = CanvasImageSource & { close?: () => void };

/** Turns a tile's base64 PNG into something a canvas can draw. */
export type TileDecoder = (pngBase64: string) => Promise<DecodedTile>;

/** The bytes of a base64 string. */
export function base64ToBytes(base64: string): Uint8Array<ArrayBuffer> {
  const binary = atob(base64);
  const bytes = new Uint8Array(binary.length);
  for (let i = 0; i < binary.length; i++) bytes[i] = binary.charCodeAt(i);
  return bytes;
}

/**
 * Decodes a PNG with `createImageBitmap` where the browser has it (off the main thread), else
 * through an `<img>` loading a data URL.
 */
export const decodeTile: TileDecoder = async (pngBase64) => {
  if (typeof createImageBitmap === 'function') {
    return createImageBitmap(new Blob([base64ToBytes(pngBase64)], { type: 'image/png' }));
  }
  const image = new Image();
  image.src = `data:image/png;base64,${pngBase64}`;
  await image.decode();
  return image;
};

/** Sets a canvas to the image's size and clears it, ready for the tiles of a new job. */
export function resetCanvas(canvas: HTMLCanvasElement | null, width: number, height: number): void {
  if (!canvas) return;
  if (width > 0 && height > 0) {
    // Assigning the size also clears the canvas, even when it did not change.
    canvas.width = width;
    canvas.height = height;
  }
  canvas.getContext('2d')?.clearRect(0, 0, canvas.width, canvas.height);
}

/**
 * Decodes a tile and draws it at its place. `stillWanted` is asked after decoding, so a tile of
 * a job that has since been replaced is dropped rather than painted over the new one.
 * Resolves false when nothing was drawn.
 */
export async function paintTile(
  canvas: () => HTMLCanvasElement | null,
  tile: JobTile,
  decode: TileDecoder = decodeTile,
  stillWanted: () => boolean = () => true,
): Promise<boolean> {
  const image = await decode(tile.png);
  try {
    const context = stillWanted() ? canvas()?.getContext('2d') : null;
    if (!context) return false;
    context.drawImage(image, tile.x, tile.y, tile.width, tile.height);
    return true;
  } finally {
    image.close?.();
  }
}
