import { useState, type DragEvent, type ReactNode } from 'react';

/** Props of {@link StageDropZone}. */
export interface StageDropZoneProps {
  /** Called with the files dropped. */
  onFiles: (files: File[]) => void;
  /** Classes of the zone's element (it takes the stage's place in the layout). */
  className: string;
  children: ReactNode;
}

const carriesFiles = (event: DragEvent) => [...event.dataTransfer.types].includes('Files');

/** The stage as a drop target for files: while files are dragged over it, it says what a drop does. */
export function StageDropZone({ onFiles, className, children }: StageDropZoneProps) {
  const [over, setOver] = useState(false);
  return (
    <div
      className={`${className} stage-drop${over ? ' is-over' : ''}`}
      data-testid="stage-drop"
      onDragOver={(event) => {
        if (!carriesFiles(event)) return;
        event.preventDefault();
        event.dataTransfer.dropEffect = 'copy';
        setOver(true);
      }}
      onDragLeave={(event) => {
        if (!event.currentTarget.contains(event.relatedTarget as Node | null)) setOver(false);
      }}
      onDrop={(event) => {
        if (!carriesFiles(event)) return;
        event.preventDefault();
        setOver(false);
        onFiles([...event.dataTransfer.files]);
      }}
    >
      {children}
      {over && (
        <div className="stage-drop__hint" aria-hidden="true">
          Drop .obj, .glb, .gltf to add a model; .png, .jpg to texture the selected object
        </div>
      )}
    </div>
  );
}
