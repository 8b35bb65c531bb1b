/**
 * Server validation errors shown next to the inputs they name. A parent provides
 * `fieldErrors: Record<string, string>` keyed by scene JSON path (`objects[2].radius`,
 * `image.width`, `camera.fov`); every input whose `data-field` path matches shows the message
 * in an element of class `field-error`.
 */
import { createContext, useContext, type ReactNode } from 'react';
import type { FieldErrors } from '../model/standingErrors';

export type { FieldErrors };

const FieldErrorsContext = createContext<FieldErrors>({});

/** Props of {@link FieldErrorsProvider}. */
export interface FieldErrorsProviderProps {
  /** The current errors; `{}` for none. */
  errors: FieldErrors;
  children: ReactNode;
}

/** Makes `errors` available to every field below it. */
export function FieldErrorsProvider({ errors, children }: FieldErrorsProviderProps) {
  return <FieldErrorsContext.Provider value={errors}>{children}</FieldErrorsContext.Provider>;
}

/** The message for one JSON path, if there is one. */
export function useFieldError(path: string): string | undefined {
  return useContext(FieldErrorsContext)[path];
}

/** All current errors (for summaries). */
export function useFieldErrors(): FieldErrors {
  return useContext(FieldErrorsContext);
}

/** Props of {@link FieldErrorMessage}. */
export interface FieldErrorMessageProps {
  /** The message, or undefined for none. */
  message?: string;
  /** Element id, for the input's `aria-describedby`. */
  id: string;
  /** The path it belongs to (`data-field-error`), so tests and styles can find it. */
  path: string;
}

/** The red message under an input. */
export function FieldErrorMessage({ message, id, path }: FieldErrorMessageProps) {
  if (!message) return null;
  return (
    <span className="field-error" id={id} data-field-error={path}>
      {message}
    </span>
  );
}

/** Turns a server problem's list into the map the provider takes (first message per field wins). */
export function toFieldErrors(errors: { field: string; message: string }[]): FieldErrors {
  const out: FieldErrors = {};
  for (const e of errors) if (e.field && !(e.field in out)) out[e.field] = e.message;
  return out;
}
