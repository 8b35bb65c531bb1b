/**
 * The live view's socket when the user signed in with a key: a browser cannot send headers with a
 * WebSocket, so a single-use ticket is fetched first (with the key) and passed in the URL. Until the
 * ticket arrives the socket is CONNECTING; a refused ticket closes it as a lost connection would
 * (the session retries, and the 401 has asked for a key meanwhile).
 */
import { apiKey } from '../api/auth';
import { fetchPreviewTicket, withTicket } from '../api/signIn';
import type { SocketFactory, SocketLike } from './liveSession';

const CONNECTING = 0;
const CLOSED = 3;

/** Opens the live view's socket: with a ticket when a key is set, else as before. */
export function signedSocketFactory(
  open: SocketFactory = (url) => new WebSocket(url),
  ticket: () => Promise<string> = () => fetchPreviewTicket(),
): SocketFactory {
  return (url) => (apiKey() ? new TicketedSocket(url, open, ticket) : open(url));
}

/** A socket that opens once its ticket has come; its handlers pass to the real one. */
class TicketedSocket implements SocketLike {
  onopen: ((event: Event) => void) | null = null;
  onmessage: ((event: MessageEvent) => void) | null = null;
  onclose: ((event: CloseEvent) => void) | null = null;
  onerror: ((event: Event) => void) | null = null;
  binaryType: BinaryType = 'blob';
  private socket: SocketLike | null = null;
  private closed = false;

  constructor(url: string, open: SocketFactory, ticket: () => Promise<string>) {
    ticket().then(
      (value) => {
        if (this.closed) return;
        const socket = open(withTicket(url, value));
        socket.binaryType = this.binaryType;
        socket.onopen = (event) => this.onopen?.(event);
        socket.onmessage = (event) => this.onmessage?.(event);
        socket.onclose = (event) => this.onclose?.(event);
        socket.onerror = (event) => this.onerror?.(event);
        this.socket = socket;
      },
      (error: unknown) => {
        if (this.closed) return;
        this.closed = true;
        const reason = error instanceof Error ? error.message : String(error);
        this.onclose?.({ code: 1006, reason, wasClean: false } as CloseEvent);
      },
    );
  }

  get readyState(): number {
    return this.socket ? this.socket.readyState : this.closed ? CLOSED : CONNECTING;
  }

  get bufferedAmount(): number {
    return this.socket?.bufferedAmount ?? 0;
  }

  send(data: string): void {
    this.socket?.send(data);
  }

  close(code?: number, reason?: string): void {
    this.closed = true;
    this.socket?.close(code, reason);
  }
}
