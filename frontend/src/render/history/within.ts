/**
 * A promise bounded in time: `promise`'s value, or `fallback` if it has not settled within
 * `timeoutMs` (or if it rejects). For storage and image decoding, which the editor never waits on
 * for long and never fails for.
 */
export function within<T>(promise: Promise<T>, timeoutMs: number, fallback: T): Promise<T> {
  return new Promise<T>((resolve) => {
    const timer = setTimeout(() => resolve(fallback), timeoutMs);
    promise.then(
      (value) => {
        clearTimeout(timer);
        resolve(value);
      },
      () => {
        clearTimeout(timer);
        resolve(fallback);
      },
    );
  });
}
