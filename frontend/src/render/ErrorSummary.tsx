import type { FieldError } from '../api/client';

/** Props of {@link ErrorSummary}. */
export interface ErrorSummaryProps {
  /** The server's headline, e.g. "Invalid scene". */
  title: string;
  /** The server's explanation, shown when it names no field. */
  detail?: string;
  /** The invalid fields, by JSON path. */
  errors: FieldError[];
  /** A field's name in the editor's words (`Sphere 1 › Radius`); the path itself by default. */
  describe?: (field: string) => string;
  /** A message in the editor's words; unchanged by default. */
  plain?: (message: string) => string;
}

const same = (text: string) => text;

/** The summary of a rejected scene: one line per invalid field ("Sphere 1 › Radius: message", the path as a tooltip). */
export function ErrorSummary({ title, detail, errors, describe = same, plain = same }: ErrorSummaryProps) {
  const heading =
    errors.length === 0 ? title : `${title}: ${errors.length} ${errors.length === 1 ? 'problem' : 'problems'}`;
  return (
    <div className="error-summary" role="alert" data-testid="error-summary">
      <strong>{heading}</strong>
      {errors.length === 0 && detail && <p>{plain(detail)}</p>}
      {errors.length > 0 && (
        <ul>
          {errors.map((error, index) => (
            <li key={`${error.field}-${index}`}>
              {error.field ? (
                <>
                  <span className="error-summary__field" title={error.field}>{describe(error.field)}</span>: {plain(error.message)}
                </>
              ) : (
                plain(error.message)
              )}
            </li>
          ))}
        </ul>
      )}
    </div>
  );
}

/**
 * The field errors as the editor shows them next to its inputs: `{field: message}`, with the
 * messages of a field named twice joined by "; ". Errors that name no field are left out.
 */
export function toFieldErrorMap(errors: FieldError[]): Record<string, string> {
  const map: Record<string, string> = {};
  for (const { field, message } of errors) {
    if (!field) continue;
    map[field] = map[field] ? `${map[field]}; ${message}` : message;
  }
  return map;
}
