import { useState } from 'react';
import { resolveMaterial, sceneLights } from '../model/defaults';
import { idOf } from '../model/identity';
import { inItems, sameSelection, type Selection } from '../model/selection';
import { selectDisplayScene, useSceneStore } from '../store/sceneStore';
import { useMeshLookup } from '../hooks/useMeshes';
import { labelOf, MATERIAL_LABELS, meshName, nameOf } from './labels';

/**
 * A clickable list of everything in the scene: objects and lights (by name, or kind and stable
 * number), the camera and its target. Shift/Ctrl-click adds an object or light to the selection
 * (or takes it out). Double-click (or F2 on) an object or point light to rename it (an area light
 * has no name in the format).
 */
export function SceneOutline() {
  const scene = useSceneStore(selectDisplayScene);
  const selection = useSceneStore((s) => s.selection);
  const selectedItems = useSceneStore((s) => s.selectedItems);
  const select = useSceneStore((s) => s.select);
  const toggleSelect = useSceneStore((s) => s.toggleSelect);
  const meshes = useMeshLookup();
  const [renaming, setRenaming] = useState<string | null>(null);
  const rename = (target: Selection, name: string) => {
    const s = useSceneStore.getState();
    const value = name.trim() === '' ? undefined : name.trim();
    if (target?.kind === 'object') s.setObjectField(target.index, 'name', value);
    if (target?.kind === 'light') s.setLightField(target.index, 'name', value);
    setRenaming(null);
  };
  const item = (key: string, label: string, target: Selection, detail?: string, name?: string, renamable = target?.kind === 'object' || target?.kind === 'light') => {
    // an area light is shown selected while its aim is
    const aimOf = selection?.kind === 'lightAim' && target?.kind === 'light' && selection.index === target.index;
    const selected = sameSelection(selection, target) || inItems(selectedItems, target) || aimOf;
    if (renaming === key) {
      return (
        <li key={key}>
          <input
            className="outline-rename"
            aria-label={`New name for ${label}`}
            defaultValue={name ?? ''}
            maxLength={200}
            // eslint-disable-next-line jsx-a11y/no-autofocus -- the field appears because the user asked to rename
            autoFocus
            onBlur={(e) => rename(target, e.currentTarget.value)}
            onKeyDown={(e) => {
              if (e.key === 'Enter') rename(target, e.currentTarget.value);
              if (e.key === 'Escape') setRenaming(null);
            }}
          />
        </li>
      );
    }
    return (
      <li key={key}>
        <button
          type="button"
          className={selected ? 'outline-item is-selected' : 'outline-item'}
          aria-pressed={selected}
          title={renamable ? `Select ${label} (Shift or Ctrl to add to the selection; double-click or F2 to rename)` : `Select ${label}`}
          onClick={(e) => {
            if (e.shiftKey || e.ctrlKey || e.metaKey) toggleSelect(target);
            else select(target); // a selected item stays selected (Escape or an empty click clears)
          }}
          onDoubleClick={() => renamable && setRenaming(key)}
          onKeyDown={(e) => e.key === 'F2' && renamable && setRenaming(key)}
        >
          {label}
          {detail && <span className="outline-item__detail">{detail}</span>}
        </button>
      </li>
    );
  };
  const lights = sceneLights(scene);
  return (
    <nav className="scene-outline" aria-label="Scene contents">
      <h3>Objects ({scene.objects.length})</h3>
      {scene.objects.length === 0 && <p className="hint">No objects yet: use Add sphere, box, plane or mesh.</p>}
      <ul>
        {scene.objects.map((o, i) =>
          item(idOf(o) ?? `o${i}`, o.type === 'mesh' || o.type === 'gltf' ? meshName(labelOf(o, i), meshes(o), o.type === 'gltf' ? 'glTF' : 'OBJ') : labelOf(o, i), { kind: 'object', index: i }, o.type === 'gltf' ? 'own materials' : MATERIAL_LABELS[resolveMaterial(o.material).type], o.name),
        )}
      </ul>
      <h3>Lights</h3>
      <ul>
        {lights.map((l, i) => item(idOf(l) ?? `l${i}`, labelOf(l, i), { kind: 'light', index: i }, scene.lights ? undefined : 'default', nameOf(l)))}
        {item('camera', 'Camera', { kind: 'camera' })}
        {item('target', 'Camera target', { kind: 'target' })}
      </ul>
    </nav>
  );
}
