/**
 * The maths of comparing two renders with a slider, pure: both images are drawn in one frame, each
 * fitted whole and centred in it, so two renders of the same size cover exactly the same pixels and
 * the divider cuts both at the same image column. Positions are percentages of the frame's width.
 */

export interface Size {
  width: number;
  height: number;
}

/** A rectangle in frame pixels. */
export interface Rect {
  x: number;
  y: number;
  width: number;
  height: number;
}

/** Where the slider starts: the middle. */
export const START_POSITION = 50;

/** The frame both images are drawn in: the larger width and the larger height, in image pixels. */
export function compareFrame(a: Size, b: Size): Size {
  return { width: Math.max(a.width, b.width, 1), height: Math.max(a.height, b.height, 1) };
}

/**
 * Where an image sits in the frame when scaled to fit it whole and centred (CSS `object-fit:
 * contain`); an image of the frame's size fills it exactly.
 */
export function containRect(image: Size, frame: Size): Rect {
  if (image.width <= 0 || image.height <= 0) return { x: 0, y: 0, width: frame.width, height: frame.height };
  const scale = Math.min(frame.width / image.width, frame.height / image.height);
  const width = image.width * scale;
  const height = image.height * scale;
  return { x: (frame.width - width) / 2, y: (frame.height - height) / 2, width, height };
}

/** Keeps a position within 0..100, rounded to a tenth (the value the slider announces). */
export function clampPosition(position: number): number {
  if (!Number.isFinite(position)) return START_POSITION;
  return Math.round(Math.min(100, Math.max(0, position)) * 10) / 10;
}

/** The position under a pointer at `clientX`, over a frame drawn from `left` across `width` screen pixels. */
export function positionAt(clientX: number, left: number, width: number): number {
  return width > 0 ? clampPosition(((clientX - left) / width) * 100) : START_POSITION;
}

/**
 * The position after a key, as sliders do (WAI-ARIA): arrows move 1 (10 with Shift), Page Up/Down 10,
 * Home and End go to the ends; null for any other key.
 */
export function positionAfterKey(position: number, key: string, shift = false): number | null {
  const step = shift ? 10 : 1;
  switch (key) {
    case 'ArrowLeft':
    case 'ArrowDown':
      return clampPosition(position - step);
    case 'ArrowRight':
    case 'ArrowUp':
      return clampPosition(position + step);
    case 'PageDown':
      return clampPosition(position - 10);
    case 'PageUp':
      return clampPosition(position + 10);
    case 'Home':
      return 0;
    case 'End':
      return 100;
    default:
      return null;
  }
}

/** The divider's x in frame pixels. */
export function dividerX(position: number, frame: Size): number {
  return (clampPosition(position) / 100) * frame.width;
}
