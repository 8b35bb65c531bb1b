import { useAutosaveStatus } from '../store/autosave';
import { useSceneStore } from '../store/sceneStore';
import { downloadScene } from './downloadScene';

/**
 * Says, for as long as it is true, that the browser is not keeping the scene (autosave's status),
 * and offers Save. Nothing while autosave works.
 */
export function AutosaveNotice() {
  const status = useAutosaveStatus();
  if (status.state !== 'failed') return null;
  return (
    <div className="studio-message" role="alert" data-testid="autosave-notice">
      <pre>{status.message}</pre>
      <button type="button" className="small" onClick={() => downloadScene(useSceneStore.getState().scene)}>
        Save
      </button>
    </div>
  );
}
