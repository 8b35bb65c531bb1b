import { describe, expect, it, vi } from 'vitest';
import { setApiKey } from '../api/auth';
import type { SocketLike } from './liveSession';
import { signedSocketFactory } from './ticketedSocket';

/** A socket that records its URL and lets the test open or close it. */
function fakeSocket(url: string): SocketLike & { url: string } {
  return {
    url,
    readyState: 0,
    bufferedAmount: 0,
    binaryType: 'blob',
    onopen: null,
    onmessage: null,
    onclose: null,
    onerror: null,
    send: vi.fn(),
    close: vi.fn(),
  };
}

describe('signedSocketFactory', () => {
  it('opens the socket directly while no key is set (sign-in off)', () => {
    const open = vi.fn(fakeSocket);
    const ticket = vi.fn(async () => 't');
    signedSocketFactory(open, ticket)('ws://h/api/preview');
    expect(open).toHaveBeenCalledWith('ws://h/api/preview');
    expect(ticket).not.toHaveBeenCalled();
  });

  it('gets a ticket first when a key is set, then opens with it and passes the events through', async () => {
    setApiKey('k');
    const sockets: ReturnType<typeof fakeSocket>[] = [];
    const open = vi.fn((url: string) => {
      const socket = fakeSocket(url);
      sockets.push(socket);
      return socket;
    });
    const socket = signedSocketFactory(open, async () => 'ticket-1')('ws://h/api/preview');
    socket.binaryType = 'arraybuffer';
    const opened = vi.fn();
    socket.onopen = opened;
    expect(socket.readyState).toBe(0);
    expect(open).not.toHaveBeenCalled();

    await vi.waitFor(() => expect(open).toHaveBeenCalledWith('ws://h/api/preview?ticket=ticket-1'));
    expect(sockets[0].binaryType).toBe('arraybuffer');
    sockets[0].onopen?.(new Event('open'));
    expect(opened).toHaveBeenCalled();
    socket.send('{"revision":1}');
    expect(sockets[0].send).toHaveBeenCalledWith('{"revision":1}');
  });

  it('closes as a lost connection when no ticket comes', async () => {
    setApiKey('k');
    const open = vi.fn(fakeSocket);
    const socket = signedSocketFactory(open, async () => {
      throw new Error('Unauthorized');
    })('ws://h/api/preview');
    const closed = vi.fn();
    socket.onclose = closed;
    await vi.waitFor(() => expect(closed).toHaveBeenCalledWith(expect.objectContaining({ code: 1006, reason: 'Unauthorized' })));
    expect(socket.readyState).toBe(3);
    expect(open).not.toHaveBeenCalled();
  });

  it('opens nothing when closed before the ticket came', async () => {
    setApiKey('k');
    const open = vi.fn(fakeSocket);
    let give: (t: string) => void = () => undefined;
    const socket = signedSocketFactory(open, () => new Promise<string>((resolve) => (give = resolve)))('ws://h/api/preview');
    socket.close(1000, 'view closed');
    give('late');
    await Promise.resolve();
    expect(open).not.toHaveBeenCalled();
  });
});
