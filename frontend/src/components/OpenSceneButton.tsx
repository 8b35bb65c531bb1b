import { useId, type ChangeEvent } from 'react';
import type { Scene } from '../model/types';
import { describeErrors, parseScene } from '../model/validate';

/** Props of {@link OpenSceneButton}. */
export interface OpenSceneButtonProps {
  /** Called with a scene file that parsed and has a scene's shape. */
  onOpen: (scene: Scene, fileName: string) => void;
  /** Called with a readable message when the file is not a scene. */
  onError: (message: string) => void;
}

/** "Open…": picks a `.json` scene file, checks it and hands it over (or explains what is wrong). */
export function OpenSceneButton({ onOpen, onError }: OpenSceneButtonProps) {
  const id = useId();
  const onChange = async (event: ChangeEvent<HTMLInputElement>) => {
    const input = event.currentTarget;
    const file = input.files?.[0];
    if (!file) return;
    try {
      const result = parseScene(await file.text());
      if (result.ok) onOpen(result.scene, file.name);
      else onError(`Cannot open ${file.name}: it is not a scene file.\n${describeErrors(result.errors)}`);
    } catch (error) {
      onError(`Cannot read ${file.name}: ${error instanceof Error ? error.message : String(error)}`);
    } finally {
      input.value = '';
    }
  };
  return (
    <label className="button file-button" htmlFor={id} title="Open a scene file (.json) from your computer">
      Open…
      <input id={id} className="visually-hidden" type="file" accept=".json,application/json" aria-label="Open scene file" data-testid="open-scene" onChange={onChange} />
    </label>
  );
}
