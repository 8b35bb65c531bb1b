/**
 * A job's event stream read through fetch, for when the user signed in with a key: `EventSource`
 * cannot send headers. It speaks the part of server-sent events the job stream uses (`event:`,
 * `data:` lines, a blank line ending each event) and does not reconnect: a broken stream ends
 * CLOSED with an `error` event, as an EventSource that gave up.
 */
import { authorizedFetch } from './auth';
import type { FetchFn } from './client';
import type { EventSourceLike } from './jobs';

const OPEN = 1;
const CLOSED = 2;

/** Opens `url` as an event stream through `fetchFn` (the key-sending fetch by default). */
export function fetchEventSource(url: string, fetchFn: FetchFn = authorizedFetch()): EventSourceLike {
  const listeners = new Map<string, ((event: MessageEvent) => void)[]>();
  const abort = new AbortController();
  let readyState = 0;
  const dispatch = (type: string, data = '') => {
    for (const listener of listeners.get(type) ?? []) listener(new MessageEvent(type, { data }));
  };
  const fail = () => {
    if (readyState === CLOSED) return;
    readyState = CLOSED;
    dispatch('error');
  };

  (async () => {
    const response = await fetchFn(url, { headers: { Accept: 'text/event-stream' }, signal: abort.signal });
    if (!response.ok || !response.body) return fail();
    readyState = OPEN;
    const reader = response.body.pipeThrough(new TextDecoderStream()).getReader();
    let buffer = '';
    let type = 'message';
    let data: string[] = [];
    for (;;) {
      const { value, done } = await reader.read();
      if (done) return fail();
      buffer += value;
      let newline: number;
      while ((newline = buffer.search(/\r?\n/)) >= 0) {
        const line = buffer.slice(0, newline);
        buffer = buffer.slice(buffer[newline] === '\r' ? newline + 2 : newline + 1);
        if (line === '') {
          if (data.length > 0) dispatch(type, data.join('\n'));
          type = 'message';
          data = [];
        } else if (line.startsWith('event:')) {
          type = line.slice(6).trim();
        } else if (line.startsWith('data:')) {
          data.push(line.slice(5).replace(/^ /, ''));
        }
        if (readyState === CLOSED) return;
      }
    }
  })().catch(fail);

  return {
    get readyState() {
      return readyState;
    },
    addEventListener(type, listener) {
      listeners.set(type, [...(listeners.get(type) ?? []), listener]);
    },
    close() {
      readyState = CLOSED;
      abort.abort();
    },
  };
}
