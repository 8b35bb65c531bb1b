import { useCallback } from 'react';
import type { ApiError, FetchFn } from '../api/client';
import { useSceneExamples } from '../hooks/useSceneExamples';
import type { AddableType } from '../model/types';
import { describeErrors, validateScene } from '../model/validate';
import type { Panels } from '../layout';
import { useSceneStore } from '../store/sceneStore';
import { IMPORT_ACCEPT } from '../model/importFiles';
import { FilePickButton } from './FilePickButton';
import { downloadScene } from './downloadScene';
import { ExamplesMenu } from './ExamplesMenu';
import { OpenSceneButton } from './OpenSceneButton';
import { SignInStatus } from './SignInStatus';
import { OBJECT_HINTS, OBJECT_LABELS } from './labels';

/** Props of {@link Toolbar}. */
export interface ToolbarProps {
  /** The fetch for the example gallery; the browser's by default. */
  fetchFn?: FetchFn;
  /** Shows a message to the user (an error opening a file or an example), or clears it with null. */
  onMessage: (message: string | null) => void;
  /** Which side panels are shown, and the way to show or hide them; no toggles without it. */
  panels?: Panels;
  onPanels?: (panels: Panels) => void;
  /** Imports files (+ Import, + Mesh): see `import/useImport.ts`; no import buttons without it. */
  onImport?: (files: File[]) => void;
  /** Shows the keyboard shortcuts (the `?` panel); no button without it. */
  onHelp?: () => void;
}

const ADDABLE: AddableType[] = ['sphere', 'box', 'plane'];

/** The top bar: file (New, Open, Save, Examples), edit (Undo, Redo, Duplicate, Delete), add, snapping. */
export function Toolbar({ fetchFn, onMessage, panels, onPanels, onHelp, onImport }: ToolbarProps) {
  const s = useSceneStore.getState();
  const canUndo = useSceneStore((st) => st.past.length > 0);
  const canRedo = useSceneStore((st) => st.future.length > 0);
  const editable = useSceneStore((st) => st.selection?.kind === 'object' || st.selection?.kind === 'light' || st.selection?.kind === 'lightAim');
  const snap = useSceneStore((st) => st.snap);
  const gridSize = useSceneStore((st) => st.gridSize);
  const showApiError = useCallback(
    (e: ApiError) => onMessage(`Could not load the examples from the server (${e.title}${e.detail ? `: ${e.detail}` : ''}). Everything else works offline.`),
    [onMessage],
  );
  const examples = useSceneExamples(fetchFn, showApiError);

  const pickExample = async (name: string) => {
    onMessage(null);
    const json = await examples.load(name);
    if (json === null) return;
    const result = validateScene(json);
    if (result.ok) s.loadScene(result.scene);
    else onMessage(`The example ${name} is not a scene this editor can read.\n${describeErrors(result.errors)}`);
  };
  const save = () => downloadScene(useSceneStore.getState().scene);

  return (
    <div className="toolbar" role="toolbar" aria-label="Scene tools">
      <h1 className="toolbar__title">Ray Studio</h1>
      <div className="toolbar__group" aria-label="File">
        <button type="button" onClick={() => { onMessage(null); s.newScene(); }} title="Start a blank scene (Undo brings the old one back)">
          New
        </button>
        <OpenSceneButton onOpen={(scene) => { onMessage(null); s.loadScene(scene); }} onError={onMessage} />
        <button type="button" onClick={save} title="Download the scene as a .json file named after the scene">
          Save
        </button>
        <ExamplesMenu scenes={examples.scenes} loading={examples.loading} onPick={pickExample} />
      </div>
      <div className="toolbar__group" aria-label="Edit">
        <button type="button" onClick={s.undo} disabled={!canUndo} title="Undo (Ctrl+Z)">
          Undo
        </button>
        <button type="button" onClick={s.redo} disabled={!canRedo} title="Redo (Ctrl+Shift+Z or Ctrl+Y)">
          Redo
        </button>
        <button type="button" onClick={s.duplicateSelected} disabled={!editable} title="Duplicate the selected object or light (Ctrl+D)">
          Duplicate
        </button>
        <button type="button" onClick={s.deleteSelected} disabled={!editable} title="Delete the selected object or light (Delete)">
          Delete
        </button>
      </div>
      <div className="toolbar__group" aria-label="Add">
        {ADDABLE.map((kind) => (
          <button key={kind} type="button" data-testid={`add-${kind}`} aria-label={`Add ${kind}`} title={`Add a ${kind}. ${OBJECT_HINTS[kind]}`} onClick={() => s.addObject(kind)}>
            + {OBJECT_LABELS[kind]}
          </button>
        ))}
        {onImport && (
          <>
            <FilePickButton
              ariaLabel="Add mesh"
              title="Add a triangle mesh from a Wavefront OBJ file, uploaded once and named by its id, on the floor in front of the camera, scaled to about 2 m"
              accept=".obj"
              testId="add-mesh"
              onFiles={onImport}
            >
              + Mesh
            </FilePickButton>
            <FilePickButton
              ariaLabel="Import files"
              title="Import .obj and .glb/.gltf models (added in front of the camera) and .png/.jpg images (the selected object's texture); or drop them on the stage"
              accept={IMPORT_ACCEPT}
              multiple
              testId="import-file"
              onFiles={onImport}
            >
              + Import
            </FilePickButton>
          </>
        )}
        <button type="button" data-testid="add-light" aria-label="Add light" title="Add a white point light (give it a radius for soft shadows)" onClick={s.addLight}>
          + Light
        </button>
        <button
          type="button"
          data-testid="add-area-light"
          aria-label="Add area light"
          title="Add a white rectangular light 3 m above the camera's target, facing the floor (soft shadows)"
          onClick={s.addAreaLight}
        >
          + Area light
        </button>
      </div>
      {panels && onPanels && (
        <div className="toolbar__group" aria-label="Panels">
          <button type="button" aria-pressed={panels.views} onClick={() => onPanels({ ...panels, views: !panels.views })} title="Show or hide the top and side views">
            2D views
          </button>
          <button type="button" aria-pressed={panels.inspector} onClick={() => onPanels({ ...panels, inspector: !panels.inspector })} title="Show or hide the inspector">
            Inspector
          </button>
        </div>
      )}
      {onHelp && (
        <div className="toolbar__group" aria-label="Help">
          <button type="button" onClick={onHelp} aria-label="Keyboard shortcuts" title="Keyboard shortcuts (?)">
            ?
          </button>
        </div>
      )}
      <SignInStatus fetchFn={fetchFn} />
      <div className="toolbar__group" aria-label="Grid">
        <label className="toolbar__check" title="Dragged things land on grid points">
          <input type="checkbox" checked={snap} onChange={(e) => s.setSnap(e.target.checked)} /> Snap to grid
        </label>
        <label className="toolbar__grid" title="Grid spacing in metres (also the snapping step)">
          Grid (m)
          <select value={gridSize} onChange={(e) => s.setGridSize(Number(e.target.value))} aria-label="Grid size in metres">
            {[0.1, 0.25, 0.5, 1, 2, 5].map((g) => (
              <option key={g} value={g}>{g}</option>
            ))}
          </select>
        </label>
      </div>
    </div>
  );
}
