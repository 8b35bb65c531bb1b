import { useCallback, useEffect, useRef, useState, type RefObject } from 'react';
import type { ApiError } from '../api/client';
import { toFieldErrorMap } from '../render/ErrorSummary';
import { decodeImage as browserDecodeImage, type ImageDecoder } from './framePainter';
import { LiveSession, type LiveConnection, type SocketFactory } from './liveSession';
import { previewUrl, type FrameHeader } from './protocol';
import { signedSocketFactory } from './ticketedSocket';

/** What the live view shows, and the injection points for tests (each defaults to the browser's own). */
export interface LivePreviewOptions {
  /** The scene to show: the committed scene, or a drag's transient preview of it. */
  scene: unknown;
  /** The view's size in device pixels. */
  width: number;
  height: number;
  /**
   * Receives the field errors of a refused scene as `{field: message}`, and `{}` when a newer
   * revision renders or the view closes (only if it had reported some).
   */
  onFieldErrors?: (errors: Record<string, string>) => void;
  socketFactory?: SocketFactory;
  decodeImage?: ImageDecoder;
  /** The socket's address; `/api/preview` on the page's host by default. */
  url?: string;
}

/** The live view's state: frames themselves go straight onto the canvas, never through state. */
export interface LivePreview {
  /** Attach to the view's canvas. */
  canvasRef: RefObject<HTMLCanvasElement | null>;
  /** The header of the frame on the canvas; null before the first. */
  frame: FrameHeader | null;
  /** The newest revision sent (0 before the first): the picture is up to date when the frame shows it. */
  sentRevision: number;
  /** The server's refusal of the newest scene; null once a newer one renders. */
  problem: ApiError | null;
  connection: LiveConnection;
  /** Connects again now, after the view gave up. */
  reconnect: () => void;
}

/** The browser's WebSocket; with an API key set, opened with a ticket (a browser cannot send the key). */
const browserSocket: SocketFactory = signedSocketFactory();

/**
 * Keeps a WebSocket to the server's live renderer open while mounted: every change of scene or
 * size becomes a revision (at most one per animation frame, the newest), every frame is drawn
 * on the canvas, a dropped connection reconnects and sends the current scene again.
 */
export function useLivePreview(options: LivePreviewOptions): LivePreview {
  const { scene, width, height } = options;
  const canvasRef = useRef<HTMLCanvasElement | null>(null);
  const [frame, setFrame] = useState<FrameHeader | null>(null);
  const [sentRevision, setSentRevision] = useState(0);
  const [problem, setProblem] = useState<ApiError | null>(null);
  const [connection, setConnection] = useState<LiveConnection>({ state: 'connecting' });
  const optionsRef = useRef(options);
  const session = useRef<LiveSession | null>(null);

  useEffect(() => {
    optionsRef.current = options;
  });

  useEffect(() => {
    const { socketFactory, decodeImage, url } = optionsRef.current;
    let reportedFieldErrors = false;
    const reportFieldErrors = (errors: Record<string, string>) => {
      if (!reportedFieldErrors && Object.keys(errors).length === 0) return;
      reportedFieldErrors = Object.keys(errors).length > 0;
      optionsRef.current.onFieldErrors?.(errors);
    };
    const live = new LiveSession({
      url: url ?? previewUrl(window.location),
      socketFactory: socketFactory ?? browserSocket,
      decodeImage: decodeImage ?? browserDecodeImage,
      canvas: () => canvasRef.current,
      onFrame: setFrame,
      onProblem: (p) => {
        setProblem(p?.error ?? null);
        reportFieldErrors(p?.error.status === 400 ? toFieldErrorMap(p.error.errors) : {});
      },
      onConnection: setConnection,
      onSent: setSentRevision,
    });
    session.current = live;
    return () => {
      live.dispose();
      session.current = null;
      reportFieldErrors({});
    };
  }, []);

  useEffect(() => session.current?.show(scene, width, height), [scene, width, height]);

  const reconnect = useCallback(() => session.current?.reconnect(), []);
  return { canvasRef, frame, sentRevision, problem, connection, reconnect };
}
