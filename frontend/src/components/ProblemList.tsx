import type { Selection } from '../model/selection';
import { selectDisplayScene, useSceneStore } from '../store/sceneStore';
import { useFieldErrors } from './fieldErrors';
import { describeField } from './fieldWords';

/** What a field path belongs to: `objects[2].radius` → object 2, `camera.fov` → the camera. */
export function selectionForPath(path: string): Selection {
  const m = /^(objects|lights)\[(\d+)\]/.exec(path);
  if (m) return { kind: m[1] === 'objects' ? 'object' : 'light', index: Number(m[2]) };
  if (path.startsWith('camera.lookAt')) return { kind: 'target' };
  if (path.startsWith('camera')) return { kind: 'camera' };
  return null;
}

/**
 * Every field error, the editor's own and the server's, as a list in the inspector's words
 * (`Sphere 2 › Radius: must be greater than 0`, the JSON path as a tooltip); each links to what it concerns.
 */
export function ProblemList() {
  const errors = Object.entries(useFieldErrors());
  const select = useSceneStore((s) => s.select);
  const scene = useSceneStore(selectDisplayScene);
  if (errors.length === 0) return null;
  return (
    <section className="problem-list" aria-label="Problems" data-testid="problem-list">
      <h3>{errors.length === 1 ? '1 problem' : `${errors.length} problems`} to fix before rendering</h3>
      <ul>
        {errors.map(([path, message]) => {
          const target = selectionForPath(path);
          const where = describeField(scene, path);
          return (
            <li key={path}>
              {target ? (
                <button type="button" className="link" onClick={() => select(target)} title={`${path} — select it to see the field`}>
                  {where}
                </button>
              ) : (
                <span title={path}>{where}</span>
              )}
              : {message}
            </li>
          );
        })}
      </ul>
    </section>
  );
}
