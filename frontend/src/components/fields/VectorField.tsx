import type { Vec3 } from '../../model/types';
import { FieldErrorMessage, useFieldError } from '../fieldErrors';
import { NumberField } from './NumberField';

const XYZ = ['x', 'y', 'z'] as const;

/** Props of {@link VectorField}. */
export interface VectorFieldProps<V extends number[] = Vec3> {
  /** Group label, e.g. "Center"; each input is labelled "Center x", "Center y", "Center z". */
  label: string;
  /** JSON path of the vector (`objects[0].center`); components get `[0]`, `[1]`, `[2]`. */
  path: string;
  value: V;
  /** Called with the whole new vector when one component is committed. */
  onCommit: (value: V) => void;
  /** The components' tags, one per component: x, y, z unless given (an area light's size: w, h). */
  axes?: readonly string[];
  step?: number;
  /** Lower bound of every component (e.g. sizes must be positive). */
  min?: number;
  /** `min` itself is refused. */
  minExclusive?: boolean;
  hint?: string;
}

/** Numeric inputs in a row for one [x, y, z] value (or as many components as `axes` names). */
export function VectorField<V extends number[] = Vec3>({ label, path, value, onCommit, axes = XYZ, step = 0.1, min, minExclusive, hint }: VectorFieldProps<V>) {
  const groupError = useFieldError(path);
  const errorId = `${path}-error`;
  return (
    <fieldset className="vector-field" title={hint} aria-describedby={groupError ? errorId : undefined}>
      <legend>{label}</legend>
      <div className="vector-field__inputs">
        {axes.map((axis, i) => (
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
              const next = [...value] as V;
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
