/** Which side panels of the editor are shown; the stage (the image) takes the rest. */
export interface Panels {
  /** The top and side views, left. */
  views: boolean;
  /** The inspector, right. */
  inspector: boolean;
}

/**
 * The panels a window of this width starts with: below 1280 CSS pixels the 2D views start hidden,
 * so that the image keeps most of the width (a 1024-pixel window leaves it about 700).
 */
export function initialPanels(windowWidth: number): Panels {
  return { views: windowWidth >= 1280, inspector: true };
}
