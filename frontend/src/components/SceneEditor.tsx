/** Props of {@link SceneEditor}. */
export interface SceneEditorProps {
  /** The scene JSON text. */
  value: string;
  /** Called with the new text on every edit. */
  onChange: (text: string) => void;
  /** Disables editing, e.g. while an example loads. */
  disabled?: boolean;
}

/** A large monospace text area holding the scene JSON. */
export function SceneEditor({ value, onChange, disabled = false }: SceneEditorProps) {
  return (
    <div className="field field--grow">
      <label htmlFor="scene-editor">Scene JSON</label>
      <textarea
        id="scene-editor"
        className="scene-editor"
        value={value}
        disabled={disabled}
        spellCheck={false}
        autoComplete="off"
        autoCapitalize="off"
        placeholder="Choose an example above, or paste a scene here."
        onChange={(event) => onChange(event.target.value)}
      />
    </div>
  );
}
