import { useId } from 'react';
import { FieldErrorMessage, useFieldError } from '../fieldErrors';

/** One choice of a {@link SelectField}. */
export interface SelectOption {
  value: string;
  label: string;
  /** Tooltip explaining the choice. */
  hint?: string;
}

/** Props of {@link SelectField}. */
export interface SelectFieldProps {
  label: string;
  /** JSON path, e.g. `objects[0].material.type`. */
  path: string;
  value: string;
  options: SelectOption[];
  /** Called with the chosen value (one edit). */
  onCommit: (value: string) => void;
  hint?: string;
}

/** A labelled drop-down. */
export function SelectField({ label, path, value, options, onCommit, hint }: SelectFieldProps) {
  const id = useId();
  const error = useFieldError(path);
  return (
    <div className="field" title={hint}>
      <label htmlFor={id}>{label}</label>
      <select
        id={id}
        value={value}
        data-field={path}
        aria-invalid={error ? true : undefined}
        aria-describedby={error ? `${id}-error` : undefined}
        onChange={(event) => event.target.value !== value && onCommit(event.target.value)}
      >
        {options.map((o) => (
          <option key={o.value} value={o.value} title={o.hint}>
            {o.label}
          </option>
        ))}
      </select>
      <FieldErrorMessage id={`${id}-error`} message={error} path={path} />
    </div>
  );
}
