import { afterEach, describe, expect, it, vi } from 'vitest';
import { apiKey, authorizedFetch, setApiKey, setKeyPrompt, subscribeApiKey, withApiKey } from './auth';

const problem401 = () =>
  new Response(JSON.stringify({ status: 401, title: 'Unauthorized' }), {
    status: 401,
    headers: { 'Content-Type': 'application/problem+json', 'WWW-Authenticate': 'Bearer' },
  });

/** A server that accepts only `key`; records the Authorization header of each request. */
function server(key: string) {
  const sent: (string | null)[] = [];
  const fetchFn = vi.fn(async (_url: string, init?: RequestInit) => {
    const authorization = new Headers(init?.headers).get('Authorization');
    sent.push(authorization);
    return authorization === `Bearer ${key}` ? new Response('[]', { status: 200 }) : problem401();
  });
  return { fetchFn, sent };
}

afterEach(() => setKeyPrompt(null));

describe('authorizedFetch', () => {
  it('sends requests unchanged while no key is set (sign-in off)', async () => {
    const base = vi.fn(async () => new Response('[]'));
    const init = { headers: { Accept: 'application/json' } };
    await authorizedFetch(base)('/api/scenes', init);
    expect(base).toHaveBeenCalledWith('/api/scenes', init);
  });

  it('sends the tab\'s key as a bearer token on every request', async () => {
    setApiKey('k-1');
    const { fetchFn, sent } = server('k-1');
    const response = await authorizedFetch(fetchFn)('/api/jobs', { method: 'POST', headers: { 'Content-Type': 'application/json' } });
    expect(response.status).toBe(200);
    expect(sent).toEqual(['Bearer k-1']);
    expect(new Headers(fetchFn.mock.calls[0][1]?.headers).get('Content-Type')).toBe('application/json');
  });

  it('asks for a key on 401, keeps it for the tab and sends the request again with it', async () => {
    const { fetchFn, sent } = server('k-2');
    const prompt = vi.fn(async () => 'k-2');
    setKeyPrompt(prompt);
    const response = await authorizedFetch(fetchFn)('/api/scenes');
    expect(response.status).toBe(200);
    expect(sent).toEqual([null, 'Bearer k-2']);
    expect(prompt).toHaveBeenCalledTimes(1);
    expect(sessionStorage.getItem('studio.apiKey')).toBe('k-2');
    expect(apiKey()).toBe('k-2');
  });

  it('asks once for all the requests refused at the same time', async () => {
    const { fetchFn } = server('k-3');
    let answer: (key: string) => void = () => undefined;
    const prompt = vi.fn(() => new Promise<string | null>((resolve) => (answer = resolve)));
    setKeyPrompt(prompt);
    const signed = authorizedFetch(fetchFn);
    const both = Promise.all([signed('/api/scenes'), signed('/api/me')]);
    await vi.waitFor(() => expect(prompt).toHaveBeenCalled());
    answer('k-3');
    const statuses = (await both).map((r) => r.status);
    expect(statuses).toEqual([200, 200]);
    expect(prompt).toHaveBeenCalledTimes(1);
  });

  it('answers the 401 when the user cancels, and keeps no key', async () => {
    const { fetchFn } = server('k-4');
    setKeyPrompt(async () => null);
    const response = await authorizedFetch(fetchFn)('/api/scenes');
    expect(response.status).toBe(401);
    expect(apiKey()).toBeNull();
  });

  it('forgets a key the server refuses again', async () => {
    const { fetchFn } = server('right');
    setKeyPrompt(async () => 'wrong');
    const response = await authorizedFetch(fetchFn)('/api/scenes');
    expect(response.status).toBe(401);
    expect(apiKey()).toBeNull();
  });

  it('tells subscribers when the key changes, and only then', () => {
    const listener = vi.fn();
    const unsubscribe = subscribeApiKey(listener);
    setApiKey('k-5');
    setApiKey('k-5');
    setApiKey(null);
    setApiKey('');
    unsubscribe();
    setApiKey('k-6');
    expect(listener).toHaveBeenCalledTimes(2);
  });
});

describe('withApiKey', () => {
  it('leaves the request alone without a key, and adds the header with one', () => {
    const init = { headers: { Accept: 'image/png' } };
    expect(withApiKey(init)).toBe(init);
    setApiKey('k-7');
    const headers = new Headers(withApiKey(init).headers);
    expect(headers.get('Authorization')).toBe('Bearer k-7');
    expect(headers.get('Accept')).toBe('image/png');
  });
});
