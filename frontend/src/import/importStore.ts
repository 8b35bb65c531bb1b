/** What the imports are doing, for the progress line (not the scene, not history). */
import { create } from 'zustand';
import type { ImportPhase } from './importFile';

export interface ImportState {
  /** The file being imported and its phase, or null when none is. */
  current: { name: string; phase: ImportPhase; fraction: number } | null;
  /** Files waiting after it. */
  waiting: number;
  /** What the last finished import did ("duck.glb: added as a glTF model."), until the next starts. */
  done: string | null;
}

export const useImportStore = create<ImportState>()(() => ({ current: null, waiting: 0, done: null }));
