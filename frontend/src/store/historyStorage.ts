/**
 * Undo history across a reload: the scenes before and after the present one, kept in the tab's
 * sessionStorage (it lives as long as the tab, as undo history does). Within a budget: the oldest
 * steps go first until what is kept fits, so a few large inline meshes cannot fill the storage.
 */
import { validateScene } from '../model/validate';
import type { Scene } from '../model/types';

export const HISTORY_KEY = 'ray-studio.history';
/** Characters of JSON the history may take (sessionStorage holds about 5 M per origin). */
export const HISTORY_BUDGET = 2_000_000;

interface Saved {
  /** The present scene's JSON, to tell the history belongs to the scene found on reload. */
  present: string;
  past: Scene[];
  future: Scene[];
}

/** Saves as much of the history as fits the budget (newest undo steps and every redo step first). */
export function saveHistory(present: Scene, past: Scene[], future: Scene[], storage: Storage | undefined = safeSession(), budget = HISTORY_BUDGET): void {
  if (!storage) return;
  const texts = past.map((s) => JSON.stringify(s));
  const futureTexts = future.map((s) => JSON.stringify(s));
  const presentText = JSON.stringify(present);
  let size = presentText.length + futureTexts.reduce((n, t) => n + t.length + 1, 0);
  let first = texts.length;
  while (first > 0 && size + texts[first - 1].length + 1 <= budget) size += texts[--first].length + 1;
  const body = `{"present":${JSON.stringify(presentText)},"past":[${texts.slice(first).join(',')}],"future":[${size <= budget ? futureTexts.join(',') : ''}]}`;
  try {
    storage.setItem(HISTORY_KEY, body);
  } catch {
    // over the browser's quota: keep nothing rather than a stale history
    try {
      storage.removeItem(HISTORY_KEY);
    } catch {
      // storage unavailable
    }
  }
}

/** The saved history if it belongs to `present` (the scene found on reload), else none. */
export function loadHistory(present: Scene, storage: Storage | undefined = safeSession()): { past: Scene[]; future: Scene[] } {
  const none = { past: [], future: [] };
  try {
    const text = storage?.getItem(HISTORY_KEY);
    if (!text) return none;
    const saved = JSON.parse(text) as Saved;
    if (saved.present !== JSON.stringify(present)) return none;
    const scenes = (list: unknown[]) => list.flatMap((s) => {
      const r = validateScene(s);
      return r.ok ? [r.scene] : [];
    });
    return { past: scenes(saved.past ?? []), future: scenes(saved.future ?? []) };
  } catch {
    return none;
  }
}

function safeSession(): Storage | undefined {
  try {
    return typeof sessionStorage === 'undefined' ? undefined : sessionStorage;
  } catch {
    return undefined;
  }
}
