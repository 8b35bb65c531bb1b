import { useState } from 'react';
import { meshCache, useMeshLookup } from '../hooks/useMeshes';
import type { ResolvedObjectOf, Vec3 } from '../model/types';
import { useSceneStore } from '../store/sceneStore';
import { FieldErrorMessage, useFieldError } from './fieldErrors';
import { NumberField } from './fields/NumberField';
import { VectorField } from './fields/VectorField';
import { triangleCountLabel } from './labels';
import { FilePickButton } from './FilePickButton';
import { ObjFileButton } from './ObjFileButton';
import { useImportFiles } from '../import/ImportContext';

/** Props of {@link InspectorMesh}. */
export interface InspectorMeshProps {
  /** Index of the mesh in `scene.objects`. */
  index: number;
  /** The mesh, defaults filled in. */
  mesh: ResolvedObjectOf<'mesh'>;
}

/**
 * A mesh's placement (position, uniform scale, rotation) and where its triangles come from:
 * inline OBJ, a file (read-only) or an uploaded asset, their count or why they cannot be read, and
 * "Load OBJ file…" to replace them by a local file's (one undo step): through the editor's import
 * (read in slices with progress, uploaded once and named by id), or inline where there is none.
 */
export function InspectorMesh({ index, mesh }: InspectorMeshProps) {
  const setField = useSceneStore((s) => s.setObjectField);
  const setMeshObj = useSceneStore((s) => s.setMeshObj);
  // in the editor a file goes through the import (read in slices, uploaded once); alone, inline
  const importFiles = useImportFiles();
  const state = useMeshLookup()(mesh);
  const [loadError, setLoadError] = useState<string | null>(null);
  const path = `objects[${index}]`;
  const serverErrors = [useFieldError(path), useFieldError(`${path}.obj`), useFieldError(`${path}.file`), useFieldError(`${path}.asset`)];
  const serverError = serverErrors.find((e) => e !== undefined);
  const vector = (field: string, label: string, value: Vec3, hint: string, step: number) => (
    <VectorField label={label} path={`${path}.${field}`} value={value} hint={hint} step={step} onCommit={(v) => setField(index, field, v)} />
  );
  const source = mesh.obj !== undefined ? 'inline OBJ' : mesh.asset !== undefined ? `uploaded OBJ ${mesh.asset.slice(0, 15)}…` : `file ${mesh.file ?? '(none)'}`;
  const reading = state.status === 'loading' && state.progress ? `reading… ${Math.round(100 * state.progress)}%` : 'loading…';
  const count = state.status === 'ready' ? triangleCountLabel(state.mesh.triangleCount) : state.status === 'loading' ? reading : null;
  return (
    <>
      {vector('position', 'Position', mesh.position, 'Where the OBJ’s origin goes (metres)', 0.1)}
      <NumberField
        label="Scale"
        path={`${path}.scale`}
        value={mesh.scale}
        min={0}
        minExclusive
        step={0.1}
        hint="Uniform scale of the OBJ’s coordinates (greater than 0)"
        onCommit={(v) => setField(index, 'scale', v)}
      />
      {vector('rotation', 'Rotation', mesh.rotation, 'Degrees about x, y, z, applied in order XYZ (as three.js), after the scale', 5)}
      <fieldset className="inspector-group" data-testid="mesh-source">
        <legend>Triangles</legend>
        <p className="mesh-source" title={mesh.file ? 'The file name is read-only: load an OBJ file to replace it by an inline copy' : undefined}>
          {count ? `${source}, ${count}` : source}
        </p>
        {state.status === 'error' && (
          <p className="field-error" role="alert">
            Cannot read the OBJ: {state.message}
          </p>
        )}
        {loadError && (
          <p className="field-error" role="alert">
            {loadError}
          </p>
        )}
        <FieldErrorMessage id={`${path}-mesh-error`} message={serverError} path={path} />
        {importFiles ? (
          <FilePickButton
            ariaLabel="Load OBJ file"
            title="Replace the triangles by those of a Wavefront OBJ file from your computer, read in the background and uploaded once (keeps position, scale and rotation)"
            accept=".obj"
            testId="load-obj"
            onFiles={(files) => {
              setLoadError(null);
              importFiles(files.slice(0, 1), { replaceMesh: index });
            }}
          >
            Load OBJ file…
          </FilePickButton>
        ) : (
          <ObjFileButton
            title="Replace the triangles by an inline copy of a Wavefront OBJ file from your computer (keeps position, scale and rotation)"
            testId="load-obj"
            onLoad={(text, fileName) => {
              const error = checkObj(text);
              setLoadError(error && `Cannot use ${fileName}: ${error}`);
              if (!error) setMeshObj(index, text);
            }}
            onError={setLoadError}
          >
            Load OBJ file…
          </ObjFileButton>
        )}
      </fieldset>
    </>
  );
}

/** Why OBJ text cannot become a mesh's triangles, or null when it can (parsed once, through the cache). */
function checkObj(text: string): string | null {
  const state = meshCache.parseInline(text);
  if (state.status === 'error') return state.message;
  if (state.status === 'ready' && state.mesh.triangleCount === 0) return 'it has no faces';
  return null;
}
