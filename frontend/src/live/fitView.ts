import { letterbox } from '../model/toThree';

/**
 * The largest view width or height asked for: the server's default limit
 * (studio.preview.max-width and max-height), which refuses a larger view as an invalid message.
 * A view over it is asked for at this size, keeping its aspect, and drawn scaled up.
 */
export const MAX_VIEW_PIXELS = 2048;

/** Where the live view sits in its panel and the size it asks the server for. */
export interface ViewFit {
  /** The letterboxed box in CSS pixels, relative to the panel (as the Camera view's canvas). */
  box: { width: number; height: number; left: number; top: number };
  /** The box in device pixels: the size sent with each revision (at least 1 x 1). */
  pixels: { width: number; height: number };
}

/**
 * Fits a view of the camera's aspect (image width / height) into a panel of `width` x `height`
 * CSS pixels, letterboxed like the Camera view, and measures it in device pixels so a frame is
 * drawn one image pixel per screen pixel (up to {@link MAX_VIEW_PIXELS}).
 */
export function fitView(width: number, height: number, aspect: number, devicePixelRatio: number): ViewFit {
  const box = letterbox(Math.max(1, width), Math.max(1, height), aspect > 0 && Number.isFinite(aspect) ? aspect : 1);
  const ratio = devicePixelRatio > 0 && Number.isFinite(devicePixelRatio) ? devicePixelRatio : 1;
  const scale = Math.min(ratio, MAX_VIEW_PIXELS / box.width, MAX_VIEW_PIXELS / box.height);
  return {
    box,
    pixels: { width: Math.max(1, Math.round(box.width * scale)), height: Math.max(1, Math.round(box.height * scale)) },
  };
}
