/**
 * The history strip's small copy of a render: at most 240 x 160 pixels, as JPEG. Twelve full-HD
 * renders decoded for the strip would take about 100 MB of memory (8 MB each); their thumbnails take
 * 1.5 MB (4 bytes a pixel). Returns null when the browser cannot make one (the strip then shows the image
 * itself, scaled) or when the image is that small already.
 */
import { within } from './within';

export const THUMBNAIL_WIDTH = 240;
export const THUMBNAIL_HEIGHT = 160;
/** Past this bound (a stalled decoder) the image stands in for its thumbnail. */
const THUMBNAIL_TIMEOUT_MS = 5000;

/** The size of the thumbnail of a `width` x `height` image, or null if the image fits already. */
export function thumbnailSize(width: number, height: number): { width: number; height: number } | null {
  const scale = Math.min(THUMBNAIL_WIDTH / width, THUMBNAIL_HEIGHT / height);
  if (!(scale < 1)) return null;
  return { width: Math.max(1, Math.round(width * scale)), height: Math.max(1, Math.round(height * scale)) };
}

/** A JPEG thumbnail of an image of `width` x `height`, or null. */
export function makeThumbnail(image: Blob, width: number, height: number): Promise<Blob | null> {
  const size = thumbnailSize(width, height);
  if (!size || typeof createImageBitmap !== 'function' || typeof document === 'undefined') return Promise.resolve(null);
  return within(draw(image, size.width, size.height), THUMBNAIL_TIMEOUT_MS, null);
}

async function draw(image: Blob, width: number, height: number): Promise<Blob | null> {
  const bitmap = await createImageBitmap(image, { resizeWidth: width, resizeHeight: height, resizeQuality: 'medium' });
  try {
    const canvas = document.createElement('canvas');
    canvas.width = width;
    canvas.height = height;
    const context = canvas.getContext('2d');
    if (!context || typeof canvas.toBlob !== 'function') return null;
    context.drawImage(bitmap, 0, 0);
    return await new Promise<Blob | null>((resolve) => canvas.toBlob(resolve, 'image/jpeg', 0.85));
  } finally {
    bitmap.close();
  }
}
