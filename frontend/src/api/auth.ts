/**
 * Sign-in for the editor: the API key the user typed, kept for the tab (sessionStorage), sent as
 * `Authorization: Bearer` on every request; a 401 asks the user for a key (once, however many
 * requests were refused) and sends the request again with it. With sign-in off the server never
 * answers 401, no key is ever asked for, and requests go out exactly as before.
 *
 * Pure TypeScript, no React: the dialog registers itself with {@link setKeyPrompt}.
 */

/** The `fetch` signature the clients use (as `client.ts`'s FetchFn, repeated to keep this module first). */
type Fetch = (input: string, init?: RequestInit) => Promise<Response>;

const STORAGE_KEY = 'studio.apiKey';

/** Asks the user for a key; resolves with it, or null if they cancel. */
export type KeyPrompt = () => Promise<string | null>;

let prompt: KeyPrompt | null = null;
let pending: Promise<string | null> | null = null;
const listeners = new Set<() => void>();

/** The key of this tab, or null when none was given (or storage is unavailable). */
export function apiKey(): string | null {
  try {
    return sessionStorage.getItem(STORAGE_KEY);
  } catch {
    return null;
  }
}

/** Keeps (or, with null, forgets) the key for this tab, and tells the subscribers. */
export function setApiKey(key: string | null): void {
  if ((key || null) === apiKey()) return;
  try {
    if (key) sessionStorage.setItem(STORAGE_KEY, key);
    else sessionStorage.removeItem(STORAGE_KEY);
  } catch {
    // no storage (a privacy mode): the key lives as long as nothing asks for it again
  }
  listeners.forEach((listener) => listener());
}

/** Calls `listener` whenever the key changes; returns the unsubscribe function. */
export function subscribeApiKey(listener: () => void): () => void {
  listeners.add(listener);
  return () => listeners.delete(listener);
}

/** Registers what asks the user for a key (the sign-in dialog); null unregisters it. */
export function setKeyPrompt(next: KeyPrompt | null): void {
  prompt = next;
  pending = null;
}

/** `init` with `Authorization: Bearer KEY` when a key is set; unchanged otherwise. */
export function withApiKey(init: RequestInit = {}): RequestInit {
  const key = apiKey();
  if (!key) return init;
  const headers = new Headers(init.headers);
  headers.set('Authorization', `Bearer ${key}`);
  return { ...init, headers };
}

/** Asks for a key once for all the requests refused meanwhile. */
function askForKey(): Promise<string | null> {
  if (!prompt) return Promise.resolve(null);
  if (!pending) {
    pending = prompt().finally(() => {
      pending = null;
    });
  }
  return pending;
}

/**
 * A fetch that sends the key; on 401 it asks for one and tries once more with it. A key that is
 * refused again is forgotten, and the 401 is answered (the next request asks again).
 */
export function authorizedFetch(base: Fetch = (input, init) => fetch(input, init)): Fetch {
  return async (input, init) => {
    const sentKey = apiKey();
    const response = await base(input, withApiKey(init));
    if (response.status !== 401) return response;
    const key = apiKey() !== sentKey ? apiKey() : await askForKey();
    if (!key) return response;
    setApiKey(key);
    const retried = await base(input, withApiKey(init));
    if (retried.status === 401) setApiKey(null);
    return retried;
  };
}
