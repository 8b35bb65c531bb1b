import type { Vec3 } from '../../model/types';
import { FieldErrorMessage, useFieldError } from '../fieldErrors';
import { NumberField } from './NumberField';

const AXES = ['x', 'y', 'z'] as const;

/** Props of {@link VectorField}. */
export interface VectorFieldProps {
  /** Group label, e.g. "Center"; each input is labelled "Center x", "Center y", "Center z". */
  label: string;
  /** JSON path of the vector (`objects[0].center`); components get `[0]`, `[1]`, `[2]`. */
  path: string;
  value: Vec3;
  /** Called with the whole new vector when one component is committed. */
  onCommit: (value: Vec3) => void;
  step?: number;
  /** Lower bound of every component (e.g. sizes must be positive). */
  min?: number;
  /** `min` itself is refused. */
  minExclusive?: boolean;
  hint?: string;
}

/** Three numeric inputs in a row for one [x, y, z] value. */
export function VectorField({ label, path, value, onCommit, step = 0.1, min, minExclusive, hint }: VectorFieldProps) {
  const groupError = useFieldError(path);
  const errorId = `${path}-error`;
  return (
    <fieldset className="vector-field" title={hint} aria-describedby={groupError ? errorId : undefined}>
      <legend>{label}</legend>
      <div className="vector-field__inputs">
        {AXES.map((axis, i) => (
          <NumberField
            key={axis}
            compact={axis}
            label={`${label} ${axis}`}
            path={`${path}[${i}]`}
            value={value[i]}
            step={step}
            min={min}
            minExclusive={minExclusive}
            invalid={groupError !== undefined}
            onCommit={(v) => {
              const next: Vec3 = [...value];
              next[i] = v;
              onCommit(next);
            }}
          />
        ))}
      </div>
      <FieldErrorMessage id={errorId} message={groupError} path={path} />
    </fieldset>
  );
}
