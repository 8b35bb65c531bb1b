import { useEffect, useId, useLayoutEffect, useRef, useState } from 'react';
import { FieldErrorMessage, useFieldError } from '../fieldErrors';

const HEX = /^#[0-9a-fA-F]{6}$/;

/**
 * A typed colour as the scene writes it (`#rrggbb`, lower case): `#f00`, `f00`, `FF0000` and
 * `#ff0000` are all red; anything else is null.
 */
export function parseHexColor(text: string): string | null {
  const m = /^#?([0-9a-fA-F]{3}|[0-9a-fA-F]{6})$/.exec(text.trim());
  if (!m) return null;
  const digits = m[1].length === 3 ? [...m[1]].map((d) => d + d).join('') : m[1];
  return `#${digits.toLowerCase()}`;
}

/** Why a typed colour is refused (it stays in the box with this message until fixed or reverted). */
export const COLOR_FORMAT_MESSAGE = 'must be a hex colour such as #ff8800 or #f80';

/** Props of {@link ColorField}. */
export interface ColorFieldProps {
  /** Accessible label of the swatch; the text box is labelled "`label` hex". */
  label: string;
  /** JSON path, e.g. `background`, `objects[0].material.color`. */
  path: string;
  /** `#rrggbb`. */
  value: string;
  /** One call per finished choice (picker closed, Enter, or leaving the hex box). */
  onCommit: (color: string) => void;
  /** Called while the picker is being dragged (not an undo step), if given. */
  onPreview?: (color: string) => void;
  /** Called when the swatch loses focus, to drop a preview that was never committed. */
  onPreviewEnd?: () => void;
  hint?: string;
}

/** A colour swatch (`type=color`) and its `#rrggbb` text, kept in step. */
export function ColorField({ label, path, value, onCommit, onPreview, onPreviewEnd, hint }: ColorFieldProps) {
  const id = useId();
  const swatch = useRef<HTMLInputElement>(null);
  const [text, setText] = useState(value);
  const serverError = useFieldError(path);
  useEffect(() => setText(value), [value]);

  // The native `change` event fires once the picker closes: that is the edit to keep.
  const latest = useRef({ value, onCommit });
  useLayoutEffect(() => {
    latest.current = { value, onCommit };
  });
  useEffect(() => {
    const input = swatch.current;
    const done = () => {
      const color = input!.value;
      if (color.toLowerCase() !== latest.current.value.toLowerCase()) latest.current.onCommit(color);
    };
    input?.addEventListener('change', done);
    return () => input?.removeEventListener('change', done);
  }, []);

  const commitText = () => {
    const color = parseHexColor(text);
    if (color === null) return; // stays, with its reason, until fixed or reverted (Escape)
    setText(color);
    if (color !== value.toLowerCase()) onCommit(color);
  };
  const localError = parseHexColor(text) === null ? COLOR_FORMAT_MESSAGE : undefined;
  const message = localError ?? serverError;
  return (
    <div className="field field--color" title={hint}>
      <label htmlFor={id}>{label}</label>
      <div className="color-field">
        <input
          ref={swatch}
          id={id}
          type="color"
          value={HEX.test(value) ? value.toLowerCase() : '#000000'}
          data-field={path}
          aria-invalid={message ? true : undefined}
          onChange={(event) => onPreview?.(event.target.value)}
          onBlur={() => onPreviewEnd?.()}
        />
        <input
          type="text"
          className="color-field__hex"
          aria-label={`${label} hex`}
          data-field={path}
          value={text}
          maxLength={9}
          spellCheck={false}
          aria-invalid={message ? true : undefined}
          aria-describedby={message ? `${id}-error` : undefined}
          onChange={(event) => setText(event.target.value)}
          onBlur={commitText}
          onKeyDown={(event) => {
            if (event.key === 'Enter') commitText();
            if (event.key === 'Escape') setText(value);
          }}
        />
      </div>
      <FieldErrorMessage id={`${id}-error`} message={message} path={path} />
    </div>
  );
}
