import { useSceneStore } from '../store/sceneStore';
import { InspectorCamera } from './InspectorCamera';
import { InspectorLight } from './InspectorLight';
import { InspectorObject } from './InspectorObject';
import { InspectorScene } from './InspectorScene';
import { SceneOutline } from './SceneOutline';
import { SelectionSummary } from './SelectionSummary';

/**
 * The right-hand column: what is in the scene, the selected object's or light's fields,
 * the camera and the scene-wide settings. Every input has a label and a `data-field` path.
 */
export function Inspector() {
  const selection = useSceneStore((s) => s.selection);
  return (
    <aside className="inspector" aria-label="Inspector">
      <SceneOutline />
      <SelectionSummary />
      {selection?.kind === 'object' && <InspectorObject key={`o${selection.index}`} index={selection.index} />}
      {(selection?.kind === 'light' || selection?.kind === 'lightAim') && <InspectorLight key={`l${selection.index}`} index={selection.index} />}
      {selection === null && <p className="hint">Click an object, light or the camera in a view (or in the list above) to edit it.</p>}
      <InspectorCamera active={selection?.kind === 'camera' || selection?.kind === 'target'} />
      <InspectorScene />
    </aside>
  );
}
