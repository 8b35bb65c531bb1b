import { useEffect, useId, useState, type CSSProperties, type KeyboardEvent } from 'react';
import { useDraftErrors } from '../../store/draftErrors';
import { FieldErrorMessage, useFieldError } from '../fieldErrors';

/** Props of {@link NumberField}. */
export interface NumberFieldProps {
  /** Accessible (and, unless `compact`, visible) label, e.g. "Radius". */
  label: string;
  /** Scene JSON path the field edits, e.g. `objects[2].radius`; becomes `data-field`. */
  path: string;
  value: number;
  /** Called once per edit (Enter, leaving the field, or a spinner step) with a valid, changed value. */
  onCommit: (value: number) => void;
  min?: number;
  max?: number;
  /** `min` itself is refused (a radius must be greater than 0). */
  minExclusive?: boolean;
  /** `max` itself is refused (a field of view must be less than 180). */
  maxExclusive?: boolean;
  /** Marks the input invalid for an error shown elsewhere (a vector's own message under its three inputs). */
  invalid?: boolean;
  /** Spinner step; also the arrow-key step. */
  step?: number;
  /** Whole numbers only. */
  integer?: boolean;
  /** Tooltip. */
  hint?: string;
  /** Shows only a short visible tag (e.g. "x") while the accessible label stays full. */
  compact?: string;
}

/**
 * A numeric input that keeps what the user types until they press Enter or leave the field,
 * then commits it once (so typing "1.25" is one undo step). Escape reverts. Out-of-range or
 * non-numeric text is not committed: it stays in the field, marked invalid with the reason beside
 * it, until it is fixed or reverted (Escape, or a new value from elsewhere such as Undo).
 */
export function NumberField(props: NumberFieldProps) {
  const { label, path, value, onCommit, step = 0.1, hint, compact, invalid = false } = props;
  const id = useId();
  const shown = formatNumber(value);
  const [draft, setDraft] = useState(shown);
  const [editing, setEditing] = useState(false);
  const serverError = useFieldError(path);
  // A new value from elsewhere (undo, a drag, another field) replaces whatever the field held.
  useEffect(() => {
    setDraft(shown);
    setEditing(false);
  }, [shown]);

  const localError = check(draft, props);
  const refused = !editing && localError !== undefined;
  // refused text is not in the scene: Render and the stage hear of it until it is fixed or reverted
  const report = useDraftErrors((s) => s.report);
  const refusal = refused ? localError : null;
  useEffect(() => {
    report(path, refusal);
    return () => report(path, null);
  }, [report, path, refusal]);

  const commitText = (text: string) => {
    setEditing(false);
    if (check(text, props)) return; // stays, with its reason, until fixed or reverted
    if (text.trim() !== shown && Number(text) !== value) onCommit(Number(text));
    else setDraft(shown);
  };
  const commit = () => commitText(draft);
  const onKeyDown = (event: KeyboardEvent<HTMLInputElement>) => {
    if (event.key === 'Enter') commit();
    if (event.key === 'Escape') {
      setEditing(false);
      setDraft(shown);
    }
  };
  const message = (editing || refused ? localError : undefined) ?? serverError;
  return (
    <div className={compact ? 'field field--compact' : 'field'} title={hint}>
      <label htmlFor={id}>{compact ?? label}</label>
      <input
        id={id}
        type="number"
        inputMode="decimal"
        step={step}
        min={props.min}
        max={props.max}
        value={draft}
        aria-label={compact ? label : undefined}
        aria-invalid={message || invalid ? true : undefined}
        aria-describedby={message ? `${id}-error` : undefined}
        data-field={path}
        style={compact ? ({ '--chars': Math.max(4, draft.length) } as CSSProperties) : undefined}
        onChange={(event) => {
          setDraft(event.target.value);
          // A spinner click or arrow key (no inputType) commits at once; typing waits for Enter/blur.
          const typed = (event.nativeEvent as Partial<InputEvent>).inputType;
          if (typed) setEditing(true);
          else commitText(event.target.value);
        }}
        onFocus={() => setEditing(true)}
        onBlur={commit}
        onKeyDown={onKeyDown}
      />
      <FieldErrorMessage id={`${id}-error`} message={message} path={path} />
    </div>
  );
}

type Bounds = Pick<NumberFieldProps, 'integer' | 'min' | 'max' | 'minExclusive' | 'maxExclusive'>;

/** Why a typed text is not an acceptable value, or undefined when it is (the server's wording). */
export function check(text: string, { integer, min, max, minExclusive, maxExclusive }: Bounds): string | undefined {
  const n = text.trim() === '' ? NaN : Number(text);
  if (text.trim() === '') return 'enter a number';
  if (!Number.isFinite(n)) return `"${text}" is not a number`;
  if (integer && !Number.isInteger(n)) return 'must be a whole number';
  if (min !== undefined && (minExclusive ? n <= min : n < min)) return minExclusive ? `must be greater than ${min}` : `must be at least ${min}`;
  if (max !== undefined && (maxExclusive ? n >= max : n > max)) return maxExclusive ? `must be less than ${max}` : `must be at most ${max}`;
  return undefined;
}

/** A value as the field shows it: 10 significant digits, no float noise (0.30000000000000004 → 0.3). */
export function formatNumber(value: number): string {
  return Number.isFinite(value) ? String(Number(value.toPrecision(10))) : String(value);
}
