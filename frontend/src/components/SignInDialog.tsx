import { useEffect, useLayoutEffect, useRef, useState, type FormEvent } from 'react';
import { setKeyPrompt } from '../api/auth';

/**
 * Asks for an API key when the server answers 401 (sign-in is on): a modal dialog with one password
 * field. It registers itself as the client's key prompt while mounted; Sign in resolves the prompt
 * with the key, Cancel or Escape with none. Nothing shows while the server never asks.
 */
export function SignInDialog() {
  const [resolve, setResolve] = useState<((key: string | null) => void) | null>(null);
  const [key, setKey] = useState('');
  const input = useRef<HTMLInputElement>(null);
  const open = useRef<((key: string | null) => void) | null>(null);

  useEffect(() => {
    setKeyPrompt(
      () =>
        new Promise<string | null>((done) => {
          open.current = done;
          setResolve(() => done);
        }),
    );
    return () => {
      setKeyPrompt(null);
      open.current?.(null); // the requests waiting for a key get their 401
    };
  }, []);

  // in the commit that shows the dialog, so that no keystroke lands before the field has focus
  useLayoutEffect(() => {
    if (resolve) input.current?.focus();
  }, [resolve]);

  if (!resolve) return null;
  const finish = (value: string | null) => {
    open.current = null;
    resolve(value);
    setResolve(null);
    setKey('');
  };
  const submit = (event: FormEvent) => {
    event.preventDefault();
    if (key.trim()) finish(key.trim());
  };
  return (
    <div className="sign-in" role="dialog" aria-modal="true" aria-labelledby="sign-in-title" aria-describedby="sign-in-why">
      <form
        className="sign-in__panel"
        onSubmit={submit}
        onKeyDown={(event) => {
          if (event.key === 'Escape') {
            event.stopPropagation();
            finish(null);
          }
        }}
      >
        <h2 id="sign-in-title">Sign in</h2>
        <p id="sign-in-why">This studio asks for an API key. It is kept for this tab only.</p>
        <label>
          API key
          <input ref={input} type="password" autoComplete="current-password" value={key} onChange={(e) => setKey(e.target.value)} />
        </label>
        <div className="sign-in__actions">
          <button type="submit" disabled={!key.trim()}>
            Sign in
          </button>
          <button type="button" onClick={() => finish(null)}>
            Cancel
          </button>
        </div>
      </form>
    </div>
  );
}
