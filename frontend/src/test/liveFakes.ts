/**
 * Test doubles for the live view: a WebSocket the test drives, a frame encoder as the server
 * writes frames, and image decoders. Only tests import this file.
 */
import type { DecodedImage, ImageDecoder } from '../live/framePainter';
import type { SocketFactory, SocketLike } from '../live/liveSession';
import { applyPatch } from './applyPatch';
import type { FrameHeader, PatchMessage, RevisionMessage } from '../live/protocol';

/** A frame header with plausible values for what a test does not set. */
export function frameHeader(overrides: Partial<FrameHeader> = {}): FrameHeader {
  return { revision: 1, pass: 1, width: 8, height: 6, samplesPerPixel: 1, final: false, format: 'jpeg', millis: 12, ...overrides };
}

/** A binary frame as the server sends it: big-endian header length, UTF-8 JSON header, image. */
export function encodeFrame(header: unknown, image: Uint8Array = new Uint8Array([0xff, 0xd8, 0xff, 0xd9])): ArrayBuffer {
  const json = new TextEncoder().encode(JSON.stringify(header));
  const bytes = new Uint8Array(4 + json.length + image.length);
  new DataView(bytes.buffer).setUint32(0, json.length, false);
  bytes.set(json, 4);
  bytes.set(image, 4 + json.length);
  return bytes.buffer;
}

/** A socket the test opens, feeds and closes; it records what the view sends. */
export class FakeSocket implements SocketLike {
  readyState = 0;
  bufferedAmount = 0;
  binaryType: BinaryType = 'blob';
  onopen: ((event: Event) => void) | null = null;
  onmessage: ((event: MessageEvent) => void) | null = null;
  onclose: ((event: CloseEvent) => void) | null = null;
  onerror: ((event: Event) => void) | null = null;
  readonly sent: string[] = [];
  /** How the view closed it; null while it has not. */
  closedBy: { code?: number; reason?: string } | null = null;

  constructor(readonly url: string) {}

  send(data: string): void {
    if (this.readyState !== 1) throw new Error(`send on a socket in state ${this.readyState}`);
    this.sent.push(data);
  }

  close(code?: number, reason?: string): void {
    this.readyState = 3;
    this.closedBy = { code, reason };
  }

  /** The server accepts the upgrade. */
  open(): void {
    this.readyState = 1;
    this.onopen?.(new Event('open'));
  }

  /** The server sends a message: a frame (ArrayBuffer) or a text message (objects as JSON). */
  receive(data: ArrayBuffer | object | string): void {
    const payload = data instanceof ArrayBuffer || typeof data === 'string' ? data : JSON.stringify(data);
    this.onmessage?.({ data: payload } as MessageEvent);
  }

  /** The server sends a frame with this header. */
  frame(overrides: Partial<FrameHeader> = {}): void {
    this.receive(encodeFrame(frameHeader(overrides)));
  }

  /** The connection ends from the server's side (1006: refused or lost without a close frame). */
  drop(code = 1006, reason = ''): void {
    this.readyState = 3;
    this.onerror?.(new Event('error'));
    this.onclose?.({ code, reason, wasClean: code !== 1006 } as CloseEvent);
  }

  /** The messages the view sent, parsed: whole scenes and patches. */
  messages(): (RevisionMessage | PatchMessage)[] {
    return this.sent.map((text) => JSON.parse(text) as RevisionMessage | PatchMessage);
  }

  /** The revisions the view sent, each patch applied to the scene before it, as the server reads them. */
  revisions(): RevisionMessage[] {
    const scenes = new Map<number, unknown>();
    return this.messages().map((message) => {
      const { revision, width, height } = message;
      const scene = 'patch' in message ? applyPatch(scenes.get(message.base), message.patch) : message.scene;
      scenes.set(revision, scene);
      return { revision, scene, width, height };
    });
  }
}

/** A factory that remembers every socket it opened. */
export function fakeSockets(): { factory: SocketFactory; opened: FakeSocket[]; last: () => FakeSocket } {
  const opened: FakeSocket[] = [];
  const factory: SocketFactory = (url) => {
    const socket = new FakeSocket(url);
    opened.push(socket);
    return socket;
  };
  const last = () => {
    const socket = opened.at(-1);
    if (!socket) throw new Error('no socket was opened');
    return socket;
  };
  return { factory, opened, last };
}

/** A decoded stand-in image: its bytes, and whether it was closed. */
export interface FakeImage {
  bytes: Uint8Array;
  mediaType: string;
  closed: boolean;
}

/**
 * A decoder the test completes by hand, in any order: `pending[i].finish()` resolves the i-th
 * decode, `pending[i].fail()` rejects it.
 */
export function manualDecoder(): { decode: ImageDecoder; pending: { finish: () => void; fail: () => void; image: FakeImage }[] } {
  const pending: { finish: () => void; fail: () => void; image: FakeImage }[] = [];
  const decode: ImageDecoder = (bytes, mediaType) =>
    new Promise<DecodedImage>((resolve, reject) => {
      const image: FakeImage = { bytes, mediaType, closed: false };
      const decoded = { ...image, close: () => (image.closed = true) } as unknown as DecodedImage;
      pending.push({ image, finish: () => resolve(decoded), fail: () => reject(new Error('cannot decode')) });
    });
  return { decode, pending };
}

/** A decoder that finishes at once. */
export const instantDecoder: ImageDecoder = async (bytes, mediaType) => ({ bytes, mediaType, close: () => {} }) as unknown as DecodedImage;
