/**
 * Narrowing of JSON values that came from outside (the server's answers, a file, the clipboard):
 * the checks every reader of such values makes, in one place.
 */

/** A JSON object: not null, not an array. */
export function isRecord(value: unknown): value is Record<string, unknown> {
  return typeof value === 'object' && value !== null && !Array.isArray(value);
}

/** A number that is neither NaN nor infinite. */
export function isFiniteNumber(value: unknown): value is number {
  return typeof value === 'number' && Number.isFinite(value);
}

/** The value if it is a finite number, else undefined. */
export function finite(value: unknown): number | undefined {
  return isFiniteNumber(value) ? value : undefined;
}
