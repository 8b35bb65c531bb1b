import { useEffect, useState } from 'react';
import { formatScene } from '../model/formatScene';
import { describeErrors, parseScene } from '../model/validate';
import { useSceneStore } from '../store/sceneStore';
import { SceneEditor } from './SceneEditor';

/**
 * The scene as JSON text, for power users. It follows the store while untouched; edits are
 * checked as you type and applied (one undo step) with Apply or Ctrl+Enter; Revert drops them.
 */
export function JsonTab() {
  const scene = useSceneStore((s) => s.scene);
  const setScene = useSceneStore((s) => s.setScene);
  const [text, setText] = useState(() => formatScene(scene));
  const [dirty, setDirty] = useState(false);
  useEffect(() => {
    if (!dirty) setText(formatScene(scene));
  }, [scene, dirty]);

  const result = dirty ? parseScene(text) : null;
  const apply = () => {
    if (result?.ok) {
      setScene(result.scene);
      setDirty(false);
    }
  };
  return (
    <div
      className="json-tab"
      onKeyDown={(event) => {
        if (event.key === 'Enter' && (event.ctrlKey || event.metaKey)) {
          event.preventDefault();
          apply();
        }
      }}
    >
      <SceneEditor
        value={text}
        onChange={(value) => {
          setText(value);
          setDirty(true);
        }}
      />
      <div className="json-tab__bar">
        <button type="button" className="primary" disabled={!result?.ok} onClick={apply} title="Apply the JSON to the scene (Ctrl+Enter); one undo step">
          Apply JSON
        </button>
        <button type="button" disabled={!dirty} onClick={() => setDirty(false)} title="Forget the edits and show the scene again">
          Revert
        </button>
        {!dirty && <span className="hint">In step with the editor.</span>}
        {result?.ok && <span className="hint">Valid scene; not applied yet.</span>}
      </div>
      {result && !result.ok && (
        <pre className="json-tab__errors" role="alert">
          {describeErrors(result.errors, 8)}
        </pre>
      )}
    </div>
  );
}
