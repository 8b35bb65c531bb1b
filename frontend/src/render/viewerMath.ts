/**
 * The full-size viewer's view as a pure value: `scale` screen (CSS) pixels per image pixel and the
 * screen position of the image's top-left corner. Zooming keeps the image point under the cursor
 * where it is, as an image editor does.
 */
export interface ViewerView {
  scale: number;
  x: number;
  y: number;
}

/** Zoom limits: from a thumbnail to 32 screen pixels an image pixel. */
export const MIN_SCALE = 1 / 64;
export const MAX_SCALE = 32;

const clampScale = (s: number) => Math.min(MAX_SCALE, Math.max(MIN_SCALE, s));

/** The whole image, centred, as large as fits (never enlarged past 1:1 on screen pixels). */
export function fitImage(viewW: number, viewH: number, imageW: number, imageH: number, devicePixelRatio = 1): ViewerView {
  const scale = clampScale(Math.min(viewW / imageW, viewH / imageH, 1 / devicePixelRatio));
  return { scale, x: (viewW - imageW * scale) / 2, y: (viewH - imageH * scale) / 2 };
}

/** One image pixel per device pixel, keeping the point at (px, py) on screen fixed. */
export function actualPixels(view: ViewerView, px: number, py: number, devicePixelRatio = 1): ViewerView {
  return zoomAbout(view, 1 / devicePixelRatio / view.scale, px, py);
}

/** Multiplies the scale by `factor` about the screen point (px, py). */
export function zoomAbout(view: ViewerView, factor: number, px: number, py: number): ViewerView {
  const scale = clampScale(view.scale * factor);
  const k = scale / view.scale;
  return { scale, x: px - (px - view.x) * k, y: py - (py - view.y) * k };
}

/** Moves the image by (dx, dy) screen pixels. */
export function panBy(view: ViewerView, dx: number, dy: number): ViewerView {
  return { ...view, x: view.x + dx, y: view.y + dy };
}

/** The image pixel under a screen point (continuous coordinates). */
export function imagePointAt(view: ViewerView, px: number, py: number): [number, number] {
  return [(px - view.x) / view.scale, (py - view.y) / view.scale];
}
