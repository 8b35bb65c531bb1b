/** Keeps the scene in localStorage so a reload finds it again. */
import { validateScene } from '../model/validate';
import type { Scene } from '../model/types';

export const STORAGE_KEY = 'ray-studio.scene';

/** The saved scene, or null when there is none or it no longer has a scene's shape. */
export function loadSavedScene(storage: Storage | undefined = safeStorage()): Scene | null {
  try {
    const text = storage?.getItem(STORAGE_KEY);
    if (!text) return null;
    const result = validateScene(JSON.parse(text));
    return result.ok ? result.scene : null;
  } catch {
    return null;
  }
}

/** Saves the scene; a full or unavailable storage is ignored (the editor still works). */
export function saveScene(scene: Scene, storage: Storage | undefined = safeStorage()): void {
  try {
    storage?.setItem(STORAGE_KEY, JSON.stringify(scene));
  } catch {
    // Quota exceeded or storage disabled: nothing to do.
  }
}

function safeStorage(): Storage | undefined {
  try {
    return typeof localStorage === 'undefined' ? undefined : localStorage;
  } catch {
    return undefined;
  }
}
