import type { FieldError } from '../api/client';

/** What the panel shows: a headline, an optional explanation and any bad fields. */
export interface DisplayError {
  title: string;
  detail?: string;
  errors?: FieldError[];
}

/** Props of {@link ErrorPanel}. */
export interface ErrorPanelProps {
  /** The error to show; nothing is rendered for null. */
  error: DisplayError | null;
}

/** A readable error: title, detail and one line per invalid field ("field — message"). */
export function ErrorPanel({ error }: ErrorPanelProps) {
  if (!error) return null;
  const errors = error.errors ?? [];
  return (
    <div className="error-panel" role="alert">
      <strong className="error-panel__title">{error.title}</strong>
      {error.detail && <p className="error-panel__detail">{error.detail}</p>}
      {errors.length > 0 && (
        <ul className="error-panel__fields">
          {errors.map((fieldError, index) => (
            <li key={`${fieldError.field}-${index}`}>
              {fieldError.field ? (
                <>
                  <code>{fieldError.field}</code> — {fieldError.message}
                </>
              ) : (
                fieldError.message
              )}
            </li>
          ))}
        </ul>
      )}
    </div>
  );
}
