import type { Ref } from 'react';
import type { LiveConnection } from './liveSession';
import { describeFrame } from './describeFrame';
import type { FrameHeader } from './protocol';
import type { ViewFit } from './fitView';

/** Props of {@link LiveCanvas}. */
export interface LiveCanvasProps {
  /** Receives the canvas; frames are drawn on it directly, outside React. */
  canvasRef: Ref<HTMLCanvasElement>;
  /** Where the view sits in its panel, in CSS pixels (letterboxed to the camera's aspect). */
  box: ViewFit['box'];
  /** The frame on the canvas, for the status line; null before the first. */
  frame: FrameHeader | null;
  /** The newest revision sent (`data-sent-revision`: the picture is current when `data-revision` equals it). */
  sentRevision: number;
  connection: LiveConnection;
  /** Connects again after the view gave up. */
  onReconnect: () => void;
}

/**
 * The ray-traced frames, scaled to the view, with a status line: the frame's pass, samples,
 * size and time, or how the connection is doing while there is nothing to show or it is lost.
 */
export function LiveCanvas({ canvasRef, box, frame, sentRevision, connection, onReconnect }: LiveCanvasProps) {
  const notice = connectionNotice(connection, frame !== null);
  return (
    <>
      <canvas
        ref={canvasRef}
        className="live-view__canvas"
        data-testid="ray-traced-canvas"
        role="img"
        aria-label="The scene as the server ray traces it"
        data-revision={frame?.revision}
        data-sent-revision={sentRevision}
        data-pass={frame?.pass}
        data-final={frame ? String(frame.final) : undefined}
        style={{ left: `${box.left}px`, top: `${box.top}px`, width: `${box.width}px`, height: `${box.height}px` }}
      />
      <div className="live-view__status" data-testid="ray-traced-status" data-connection={connection.state}>
        {frame && <span role="status">{describeFrame(frame)}</span>}
        {notice && <span className={connection.state === 'failed' ? 'live-view__notice is-error' : 'live-view__notice'}>{notice}</span>}
        {connection.state === 'failed' && (
          <button type="button" className="small" onClick={onReconnect}>
            Reconnect
          </button>
        )}
      </div>
    </>
  );
}

/** A sentence about the connection when there is something to say; null when all is well. */
export function connectionNotice(connection: LiveConnection, hasFrame: boolean): string | null {
  switch (connection.state) {
    case 'connecting':
      return hasFrame ? null : 'Connecting to the renderer…';
    case 'open':
    case 'paused':
      return hasFrame ? null : 'Waiting for the first frame…';
    case 'retrying':
      return `Reconnecting in ${Math.max(1, Math.round(connection.delayMillis / 1000))} s (${connection.reason})`;
    case 'failed':
      return `The live view lost the server: ${connection.reason}.`;
  }
}
