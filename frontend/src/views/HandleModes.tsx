import type { GizmoMode } from '../model/gizmo';
import { useSceneStore } from '../store/sceneStore';

const MODES: [GizmoMode, string, string][] = [
  ['translate', 'Move', 'W'],
  ['rotate', 'Rotate', 'E'],
  ['scale', 'Scale', 'R'],
];

/** Move / Rotate / Scale: which handles the 3D preview puts on the selection (also W, E, R). */
export function HandleModes() {
  const mode = useSceneStore((s) => s.gizmo);
  const setMode = useSceneStore((s) => s.setGizmo);
  return (
    <div className="segmented handle-modes" role="group" aria-label="3D handles">
      {MODES.map(([id, label, key]) => (
        <button key={id} type="button" className="small" aria-pressed={mode === id} onClick={() => setMode(id)} title={`${label} handles on the selection (${key}); F frames it`}>
          {label}
        </button>
      ))}
    </div>
  );
}
