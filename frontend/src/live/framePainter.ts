/**
 * Decoding live frames and drawing them onto the view's canvas. Pure DOM, no React: frames go
 * straight to the canvas and never through component state.
 */

/** A decoded frame, ready for `drawImage`; `close` frees an ImageBitmap's memory. */
export type DecodedImage = CanvasImageSource & { close?: () => void };

/** Turns a frame's encoded image into something a canvas can draw. */
export type ImageDecoder = (bytes: Uint8Array<ArrayBuffer>, mediaType: string) => Promise<DecodedImage>;

/**
 * Decodes with `createImageBitmap` where the browser has it (off the main thread), else
 * through an `<img>` loading an object URL.
 */
export const decodeImage: ImageDecoder = async (bytes, mediaType) => {
  const blob = new Blob([bytes], { type: mediaType });
  if (typeof createImageBitmap === 'function') return createImageBitmap(blob);
  const url = URL.createObjectURL(blob);
  try {
    const image = new Image();
    image.src = url;
    await image.decode();
    return image;
  } finally {
    URL.revokeObjectURL(url);
  }
};

/**
 * Draws a frame over the whole canvas, scaled to `width` x `height` device pixels (the view's
 * size; a coarse pass is smaller and is upscaled smoothly). The canvas is resized only here,
 * just before drawing, since resizing clears it.
 */
export function drawFrame(canvas: HTMLCanvasElement, image: DecodedImage, width: number, height: number): boolean {
  if (canvas.width !== width || canvas.height !== height) {
    canvas.width = width;
    canvas.height = height;
  }
  const context = canvas.getContext('2d');
  if (!context) return false;
  context.imageSmoothingEnabled = true;
  context.imageSmoothingQuality = 'high';
  context.drawImage(image, 0, 0, width, height);
  return true;
}
