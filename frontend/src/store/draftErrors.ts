import { create } from 'zustand';
import type { FieldErrors } from '../model/standingErrors';

/** Fields whose typed text was refused and is not in the scene, by JSON path, with the reason. */
interface DraftErrorsState {
  errors: FieldErrors;
  /** Records (a message) or clears (null) the refusal of the field at `path`. */
  report(path: string, message: string | null): void;
}

/**
 * What a person typed that the scene does not hold: a field keeps refused text on screen, marked
 * invalid, while the scene keeps its last valid value. Render refuses while any is left, and the
 * stage says that what it shows is not the scene as typed.
 */
export const useDraftErrors = create<DraftErrorsState>()((set, get) => ({
  errors: {},
  report: (path, message) => {
    const errors = get().errors;
    if (message === null ? !(path in errors) : errors[path] === message) return;
    const next = { ...errors };
    if (message === null) delete next[path];
    else next[path] = message;
    set({ errors: next });
  },
}));
