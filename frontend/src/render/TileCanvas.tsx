import type { Ref } from 'react';

/** Props of {@link TileCanvas}. */
export interface TileCanvasProps {
  /** Receives the canvas element; tiles are drawn on it directly, outside React. */
  canvasRef: Ref<HTMLCanvasElement>;
  /** The image's size in pixels, for its aspect ratio before the first tile arrives. */
  width: number;
  height: number;
  /** Hides the canvas but keeps it mounted, so the painter always has an element to draw on. */
  hidden: boolean;
}

/**
 * The canvas on which finished tiles appear as they arrive. Its pixel size is set by the
 * painter (setting it from React would clear the tiles), so only the aspect ratio is a prop.
 */
export function TileCanvas({ canvasRef, width, height, hidden }: TileCanvasProps) {
  const aspectRatio = width > 0 && height > 0 ? `${width} / ${height}` : undefined;
  return (
    <div className="render-frame" hidden={hidden}>
      <canvas
        ref={canvasRef}
        data-testid="render-canvas"
        role="img"
        aria-label="The image as its tiles finish"
        style={{ aspectRatio, width: width > 0 ? `${width}px` : undefined }}
      />
    </div>
  );
}
