import { useEffect, useId, useState } from 'react';
import { FieldErrorMessage, useFieldError } from '../fieldErrors';

/** Props of {@link TextField}. */
export interface TextFieldProps {
  label: string;
  /** JSON path, e.g. `name`. */
  path: string;
  value: string;
  /** Called once per edit (Enter or leaving the field) when the text changed. */
  onCommit: (value: string) => void;
  maxLength?: number;
  hint?: string;
}

/** A one-line text input committed on Enter or blur. */
export function TextField({ label, path, value, onCommit, maxLength, hint }: TextFieldProps) {
  const id = useId();
  const [draft, setDraft] = useState(value);
  const error = useFieldError(path);
  useEffect(() => setDraft(value), [value]);
  const commit = () => draft !== value && onCommit(draft);
  return (
    <div className="field" title={hint}>
      <label htmlFor={id}>{label}</label>
      <input
        id={id}
        type="text"
        value={draft}
        maxLength={maxLength}
        data-field={path}
        aria-invalid={error ? true : undefined}
        aria-describedby={error ? `${id}-error` : undefined}
        onChange={(event) => setDraft(event.target.value)}
        onBlur={commit}
        onKeyDown={(event) => {
          if (event.key === 'Enter') commit();
          if (event.key === 'Escape') setDraft(value);
        }}
      />
      <FieldErrorMessage id={`${id}-error`} message={error} path={path} />
    </div>
  );
}
