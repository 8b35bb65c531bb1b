import { sceneLights } from '../model/defaults';
import { sameSelection, type Selection } from '../model/selection';
import { resolveMaterial } from '../model/defaults';
import { selectDisplayScene, useSceneStore } from '../store/sceneStore';
import { useMeshLookup } from '../hooks/useMeshes';
import { MATERIAL_LABELS, meshName, objectName } from './labels';

/** A clickable list of everything in the scene: objects, lights, the camera and its target. */
export function SceneOutline() {
  const scene = useSceneStore(selectDisplayScene);
  const selection = useSceneStore((s) => s.selection);
  const select = useSceneStore((s) => s.select);
  const meshes = useMeshLookup();
  const item = (key: string, label: string, target: Selection, detail?: string) => {
    const selected = sameSelection(selection, target);
    return (
      <li key={key}>
        <button
          type="button"
          className={selected ? 'outline-item is-selected' : 'outline-item'}
          aria-pressed={selected}
          title={`Select ${label}`}
          onClick={() => select(selected ? null : target)}
        >
          {label}
          {detail && <span className="outline-item__detail">{detail}</span>}
        </button>
      </li>
    );
  };
  return (
    <nav className="scene-outline" aria-label="Scene contents">
      <h3>Objects ({scene.objects.length})</h3>
      {scene.objects.length === 0 && <p className="hint">No objects yet: use Add sphere, box, plane or mesh.</p>}
      <ul>
        {scene.objects.map((o, i) =>
          item(`o${i}`, o.type === 'mesh' ? meshName(i, meshes(o)) : objectName(o.type, i), { kind: 'object', index: i }, MATERIAL_LABELS[resolveMaterial(o.material).type]),
        )}
      </ul>
      <h3>Lights</h3>
      <ul>
        {sceneLights(scene).map((_, i) => item(`l${i}`, `Light ${i + 1}`, { kind: 'light', index: i }, scene.lights ? undefined : 'default'))}
        {item('camera', 'Camera', { kind: 'camera' })}
        {item('target', 'Camera target', { kind: 'target' })}
      </ul>
    </nav>
  );
}
