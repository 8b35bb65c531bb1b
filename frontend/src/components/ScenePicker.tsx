import type { SceneSummary } from '../api/client';

/** Props of {@link ScenePicker}. */
export interface ScenePickerProps {
  /** The examples to offer, in display order. */
  scenes: SceneSummary[];
  /** The chosen example's name, or '' before anything was chosen. */
  selected: string;
  /** Called with the name of the example the user picked. */
  onSelect: (name: string) => void;
  /** True while the list or a scene is loading. */
  loading?: boolean;
}

/** A select of the example scenes in `scenes/`. */
export function ScenePicker({ scenes, selected, onSelect, loading = false }: ScenePickerProps) {
  return (
    <div className="field">
      <label htmlFor="scene-picker">Example scene</label>
      <select
        id="scene-picker"
        value={selected}
        disabled={loading && scenes.length === 0}
        onChange={(event) => onSelect(event.target.value)}
      >
        <option value="" disabled>
          {scenes.length === 0 && loading ? 'Loading examples…' : 'Choose an example…'}
        </option>
        {scenes.map((scene) => (
          <option key={scene.name} value={scene.name}>
            {scene.name}
          </option>
        ))}
      </select>
    </div>
  );
}
