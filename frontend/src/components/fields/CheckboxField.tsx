import { useId } from 'react';
import { FieldErrorMessage, useFieldError } from '../fieldErrors';

/** Props of {@link CheckboxField}. */
export interface CheckboxFieldProps {
  label: string;
  /** JSON path, e.g. `lights[0].falloff`. */
  path: string;
  checked: boolean;
  /** Called with the new state (one edit). */
  onCommit: (checked: boolean) => void;
  hint?: string;
}

/** A labelled checkbox. */
export function CheckboxField({ label, path, checked, onCommit, hint }: CheckboxFieldProps) {
  const id = useId();
  const error = useFieldError(path);
  return (
    <div className="field field--checkbox" title={hint}>
      <input id={id} type="checkbox" checked={checked} data-field={path} aria-invalid={error ? true : undefined} onChange={(e) => onCommit(e.target.checked)} />
      <label htmlFor={id}>{label}</label>
      <FieldErrorMessage id={`${id}-error`} message={error} path={path} />
    </div>
  );
}
