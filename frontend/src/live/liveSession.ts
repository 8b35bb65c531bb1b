/**
 * One live ray-traced view's connection, without React: sends the newest scene at most once per
 * animation frame (after the first on a socket, as a patch to the one sent before, see
 * {@link encodeNext}), draws the frames that come back (never one older than a frame already
 * drawn), reports problems, and reconnects after a dropped connection.
 */
import { sameJson } from '../model/sameJson';
import { drawFrame, type ImageDecoder } from './framePainter';
import { decodeFrame, decodeProblem, encodeNext, isSameOrNewer, type Frame, type FrameHeader, type RevisionProblem } from './protocol';

/** The few members of `WebSocket` the view uses; tests pass a fake. */
export interface SocketLike {
  readonly readyState: number;
  readonly bufferedAmount: number;
  binaryType: BinaryType;
  onopen: ((event: Event) => void) | null;
  onmessage: ((event: MessageEvent) => void) | null;
  onclose: ((event: CloseEvent) => void) | null;
  onerror: ((event: Event) => void) | null;
  send(data: string): void;
  close(code?: number, reason?: string): void;
}

/** Opens a socket to a URL; the default is `new WebSocket(url)`. */
export type SocketFactory = (url: string) => SocketLike;

/** Where the connection is, for the view to show. */
export type LiveConnection =
  | { state: 'connecting' }
  | { state: 'open' }
  /** Lost before the picture was complete: trying again after `delayMillis`. */
  | { state: 'retrying'; reason: string; delayMillis: number }
  /** Closed after the picture was complete (an idle session); the next edit reconnects. */
  | { state: 'paused'; reason: string }
  /** Gave up after the last retry; the next edit, or {@link LiveSession.reconnect}, tries again. */
  | { state: 'failed'; reason: string };

/** What the session needs from its owner. */
export interface LiveSessionOptions {
  url: string;
  socketFactory: SocketFactory;
  decodeImage: ImageDecoder;
  /** The canvas frames are drawn on (looked up at each frame: it may be replaced). */
  canvas: () => HTMLCanvasElement | null;
  /** A frame was drawn. */
  onFrame: (frame: FrameHeader) => void;
  /** The server refused a revision's scene; null once a newer revision has been drawn. */
  onProblem: (problem: RevisionProblem | null) => void;
  onConnection: (connection: LiveConnection) => void;
  /** A revision was sent (at most once per animation frame). */
  onSent: (revision: number) => void;
}

/**
 * Waits before each reconnection, then gives up: about 45 s in all, long enough for a server
 * restart, short enough not to knock forever on a server that refuses the view.
 */
export const RETRY_DELAYS = [500, 1000, 2000, 4000, 8000, 10_000, 10_000, 10_000];

/**
 * Close codes for a message the server will not take (unsupported data, bad data, policy, too
 * big): the view gives up until the next edit instead of sending it again.
 */
const REFUSED_MESSAGE = new Set([1003, 1007, 1008, 1009]);

/** `WebSocket.OPEN`. */
const OPEN = 1;

/** A scene and the view size it is wanted at. */
interface View {
  scene: unknown;
  width: number;
  height: number;
}

const sameView = (a: View, b: View) => a.width === b.width && a.height === b.height && sameJson(a.scene, b.scene);

export class LiveSession {
  private socket: SocketLike | null = null;
  private connection: LiveConnection = { state: 'connecting' };
  /** The newest scene asked for. */
  private wanted: View | null = null;
  /** The newest scene sent, and what the current socket has carried (null: nothing yet). */
  private lastSent: View | null = null;
  private sentOnSocket: View | null = null;
  private revision = 0;
  /** The scene the server holds for this socket, which the next patch applies to (null: send the whole scene). */
  private base: { revision: number; scene: unknown } | null = null;
  /** The revision last sent whole: a problem of a later one was a patch's, and the whole scene follows it. */
  private wholeRevision = 0;
  /** A patch was refused: send the whole scene even though the view has not changed. */
  private resendWhole = false;
  /** The newest revision answered in full (a final frame or a problem). */
  private settled = 0;
  private drawn: FrameHeader | null = null;
  private problemRevision = -1;
  private attempts = 0;
  private frameRequest = 0;
  private retryTimer: ReturnType<typeof setTimeout> | undefined;
  private disposed = false;

  constructor(private readonly options: LiveSessionOptions) {
    this.connect();
  }

  /** Asks for a scene at a view size; sent with the next animation frame if it differs from the last. */
  show(scene: unknown, width: number, height: number): void {
    const next = { scene, width, height };
    const changed = !this.wanted || !sameView(this.wanted, next);
    this.wanted = next;
    if (!changed || this.disposed) return;
    if (this.connection.state === 'paused' || this.connection.state === 'failed') this.reconnect();
    this.requestFlush();
  }

  /** Connects again now (after giving up, or instead of waiting for the next retry). */
  reconnect(): void {
    if (this.disposed || this.connection.state === 'open' || this.connection.state === 'connecting') return;
    this.attempts = 0;
    this.connect();
  }

  /** Closes the socket and stops every timer; nothing is reported afterwards. */
  dispose(): void {
    this.disposed = true;
    cancelAnimationFrame(this.frameRequest);
    clearTimeout(this.retryTimer);
    const socket = this.socket;
    this.socket = null;
    if (socket) {
      socket.onopen = socket.onmessage = socket.onerror = null;
      socket.onclose = null;
      socket.close(1000, 'view closed');
    }
  }

  private connect(): void {
    clearTimeout(this.retryTimer);
    this.setConnection({ state: 'connecting' });
    let socket: SocketLike;
    try {
      socket = this.options.socketFactory(this.options.url);
    } catch (error) {
      this.lost(error instanceof Error ? error.message : String(error));
      return;
    }
    this.socket = socket;
    this.sentOnSocket = null;
    this.base = null;
    socket.binaryType = 'arraybuffer';
    socket.onopen = () => {
      this.setConnection({ state: 'open' });
      this.requestFlush();
    };
    socket.onmessage = (event) => this.receive(event.data);
    socket.onclose = (event) => {
      if (socket !== this.socket) return;
      this.socket = null;
      this.lost(describeClose(event), event.code);
    };
  }

  /**
   * The socket closed (or could not be made): pause, retry after a while, or give up (at once
   * when the server refused the message itself: sending it again would only be refused again).
   */
  private lost(reason: string, code = 1006): void {
    if (this.disposed) return;
    const complete = !this.wanted || (this.lastSent !== null && this.settled >= this.revision && sameView(this.lastSent, this.wanted));
    if (complete) return this.setConnection({ state: 'paused', reason });
    if (this.attempts >= RETRY_DELAYS.length || REFUSED_MESSAGE.has(code)) return this.setConnection({ state: 'failed', reason });
    const delayMillis = RETRY_DELAYS[this.attempts++];
    this.setConnection({ state: 'retrying', reason, delayMillis });
    this.retryTimer = setTimeout(() => this.connect(), delayMillis);
  }

  private requestFlush(): void {
    if (!this.frameRequest && !this.disposed) this.frameRequest = requestAnimationFrame(this.flush);
  }

  /** Sends the newest wanted scene if the socket is open, has not carried it, and has sent what it held. */
  private readonly flush = (): void => {
    this.frameRequest = 0;
    const { socket, wanted } = this;
    if (!socket || socket.readyState !== OPEN || !wanted) return;
    if (this.sentOnSocket && sameView(this.sentOnSocket, wanted) && !this.resendWhole) return;
    // A slow link still sending the last revision: wait, so only the newest one queues.
    if (socket.bufferedAmount > 0) return this.requestFlush();
    this.revision += 1;
    const { scene, width, height } = wanted;
    const { text, patched } = encodeNext(this.revision, scene, { width, height }, this.resendWhole ? null : this.base);
    socket.send(text);
    if (!patched) this.wholeRevision = this.revision;
    this.base = { revision: this.revision, scene };
    this.resendWhole = false;
    this.lastSent = this.sentOnSocket = wanted;
    this.options.onSent(this.revision);
  };

  private receive(data: unknown): void {
    if (this.disposed) return;
    if (typeof data === 'string') return this.receiveProblem(data);
    if (!(data instanceof ArrayBuffer)) return;
    let frame: Frame;
    try {
      frame = decodeFrame(data);
    } catch {
      return; // not a frame: dropped; the next frame of the revision replaces it anyway
    }
    this.attempts = 0;
    if (frame.header.final) this.settled = Math.max(this.settled, frame.header.revision);
    if (isSameOrNewer(frame.header, this.drawn)) void this.paint(frame);
  }

  private receiveProblem(text: string): void {
    const problem = decodeProblem(text);
    if (!problem) return;
    this.attempts = 0;
    // A message the server could not read whole names no revision: it can only be the newest sent.
    const revision = problem.revision ?? this.revision;
    this.settled = Math.max(this.settled, revision);
    if (revision >= this.wholeRevision) this.base = null; // the server applies no patch until the next whole scene
    if (revision > this.wholeRevision) {
      // a patch's: the whole scene follows; a problem with the patch itself is not the user's to see
      this.resendWhole = true;
      this.requestFlush();
      if (isPatchProblem(problem)) return;
    }
    if ((this.drawn && revision < this.drawn.revision) || revision < this.problemRevision) return;
    this.problemRevision = revision;
    this.options.onProblem({ ...problem, revision });
  }

  /** Decodes a frame off the main thread, then draws it unless a newer one was drawn meanwhile. */
  private async paint({ header, image: bytes, mediaType }: Frame): Promise<void> {
    let image;
    try {
      image = await this.options.decodeImage(bytes, mediaType);
    } catch {
      return; // an image the browser cannot decode is dropped like a broken frame
    }
    try {
      const canvas = this.options.canvas();
      if (this.disposed || !canvas || !this.wanted || !isSameOrNewer(header, this.drawn)) return;
      if (!drawFrame(canvas, image, this.wanted.width, this.wanted.height)) return;
      this.drawn = header;
      this.options.onFrame(header);
      if (this.problemRevision >= 0 && header.revision > this.problemRevision) {
        this.problemRevision = -1;
        this.options.onProblem(null);
      }
    } finally {
      image.close?.();
    }
  }

  private setConnection(connection: LiveConnection): void {
    this.connection = connection;
    if (!this.disposed) this.options.onConnection(connection);
  }
}

/** A problem only with a patch (its base or its operations), which sending the whole scene solves. */
function isPatchProblem({ error }: RevisionProblem): boolean {
  return error.errors.length > 0 && error.errors.every(({ field }) => field === 'base' || field === 'patch' || field.startsWith('patch['));
}

/** A close in the user's words: the server's reason when it gave one. */
export function describeClose(event: { code: number; reason: string }): string {
  if (event.reason) return event.reason;
  if (event.code === 1006) return 'the connection was refused or lost';
  if (event.code === 1001) return 'the server is going away';
  return `the connection closed (code ${event.code})`;
}
