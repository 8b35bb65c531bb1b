import type { DrawProgress } from './firstDraw';

/** Props of {@link DrawProgressNote}. */
export interface DrawProgressNoteProps {
  /** How much of the large meshes just added the preview has drawn; null: all of it (nothing shown). */
  progress: DrawProgress | null;
}

/** A line over the 3D preview while it draws a large mesh part by part: how far it is. */
export function DrawProgressNote({ progress }: DrawProgressNoteProps) {
  if (!progress) return null;
  const percent = Math.floor((100 * progress.drawn) / progress.total);
  return (
    <p className="preview3d__drawing" role="status" data-testid="preview-drawing">
      Drawing {progress.total.toLocaleString('en')} triangles: {percent}%
      <progress value={progress.drawn} max={progress.total} aria-label="Triangles drawn" />
    </p>
  );
}
