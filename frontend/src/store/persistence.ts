/**
 * The scene an earlier editor kept in localStorage: read once, when IndexedDB holds nothing yet,
 * so a scene autosaved before autosave moved to IndexedDB (`autosave.ts`) is not lost; then removed.
 */
import { validateScene } from '../model/validate';
import type { Scene } from '../model/types';

export const STORAGE_KEY = 'ray-studio.scene';

/** The scene an earlier editor saved, or null when there is none or it no longer has a scene's shape. */
export function loadLegacyScene(storage: Storage | undefined = safeStorage()): Scene | null {
  try {
    const text = storage?.getItem(STORAGE_KEY);
    if (!text) return null;
    const result = validateScene(JSON.parse(text));
    return result.ok ? result.scene : null;
  } catch {
    return null;
  }
}

/** Forgets the earlier editor's copy (once IndexedDB keeps the scene). */
export function forgetLegacyScene(storage: Storage | undefined = safeStorage()): void {
  try {
    storage?.removeItem(STORAGE_KEY);
  } catch {
    // storage unavailable: nothing to forget
  }
}

function safeStorage(): Storage | undefined {
  try {
    return typeof localStorage === 'undefined' ? undefined : localStorage;
  } catch {
    return undefined;
  }
}
