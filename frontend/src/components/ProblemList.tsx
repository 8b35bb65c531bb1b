import type { Selection } from '../model/selection';
import { useSceneStore } from '../store/sceneStore';
import { useFieldErrors } from './fieldErrors';

/** What a field path belongs to: `objects[2].radius` → object 2, `camera.fov` → the camera. */
export function selectionForPath(path: string): Selection {
  const m = /^(objects|lights)\[(\d+)\]/.exec(path);
  if (m) return { kind: m[1] === 'objects' ? 'object' : 'light', index: Number(m[2]) };
  if (path.startsWith('camera.lookAt')) return { kind: 'target' };
  if (path.startsWith('camera')) return { kind: 'camera' };
  return null;
}

/** The server's field errors as a list; each links to the object or light it concerns. */
export function ProblemList() {
  const errors = Object.entries(useFieldErrors());
  const select = useSceneStore((s) => s.select);
  if (errors.length === 0) return null;
  return (
    <section className="problem-list" aria-label="Problems found by the server">
      <h3>{errors.length === 1 ? '1 problem' : `${errors.length} problems`} to fix before rendering</h3>
      <ul>
        {errors.map(([path, message]) => {
          const target = selectionForPath(path);
          return (
            <li key={path}>
              {target ? (
                <button type="button" className="link" onClick={() => select(target)} title="Select it to see the field">
                  <code>{path}</code>
                </button>
              ) : (
                <code>{path}</code>
              )}{' '}
              {message}
            </li>
          );
        })}
      </ul>
    </section>
  );
}
