import { useEffect, useState } from 'react';
import { setApiKey, subscribeApiKey } from '../api/auth';
import type { FetchFn } from '../api/client';
import { fetchMe, type Me } from '../api/signIn';

/** Props of {@link SignInStatus}. */
export interface SignInStatusProps {
  /** The fetch for `GET /api/me`; the key-sending one by default. */
  fetchFn?: FetchFn;
}

/**
 * Who is signed in, with a Sign out button, when the server asks callers to sign in; nothing with
 * sign-in off (or while nobody is signed in). Asks the server again whenever the key changes.
 */
export function SignInStatus({ fetchFn }: SignInStatusProps) {
  const [me, setMe] = useState<Me | null>(null);
  useEffect(() => {
    let current = true;
    const ask = () =>
      fetchMe(fetchFn).then(
        (answer) => current && setMe(answer),
        () => current && setMe(null),
      );
    void ask();
    const unsubscribe = subscribeApiKey(() => void ask());
    return () => {
      current = false;
      unsubscribe();
    };
  }, [fetchFn]);

  if (!me?.signInRequired) return null;
  return (
    <div className="toolbar__group" aria-label="Sign-in">
      <span className="toolbar__signed-in">Signed in as {me.principal}</span>
      <button type="button" className="small" onClick={() => setApiKey(null)}>
        Sign out
      </button>
    </div>
  );
}
