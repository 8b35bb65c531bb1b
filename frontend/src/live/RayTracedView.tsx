import { useRef } from 'react';
import { JobApiError } from '../api/jobs';
import { useElementSize } from '../hooks/useElementSize';
import { imageAspect } from '../model/defaults';
import { ErrorSummary } from '../render/ErrorSummary';
import { fieldWordsOf } from '../render/fieldWordsOf';
import { RenderNotice } from '../render/RenderNotice';
import { selectDisplayScene, useSceneStore } from '../store/sceneStore';
import type { ImageDecoder } from './framePainter';
import { fitView } from './fitView';
import { LiveCanvas } from './LiveCanvas';
import type { SocketFactory } from './liveSession';
import { useLivePreview } from './useLivePreview';

/** Props of {@link RayTracedView}. */
export interface RayTracedViewProps {
  /** Receives the field errors of a refused scene (`{}` once the scene renders again). */
  onFieldErrors?: (errors: Record<string, string>) => void;
  /** Opens the socket; `new WebSocket(url)` by default, a fake in tests. */
  socketFactory?: SocketFactory;
  /** Decodes a frame's image; `createImageBitmap` by default, a fake in tests. */
  decodeImage?: ImageDecoder;
}

/**
 * The live ray-traced view: the scene as shown in the editor (a drag's transient position
 * included) is rendered by the server at the panel's size in device pixels, letterboxed to the
 * camera's aspect like the Camera view. A refused scene shows as the render panel shows it.
 */
export function RayTracedView({ onFieldErrors, socketFactory, decodeImage }: RayTracedViewProps) {
  const panel = useRef<HTMLDivElement>(null);
  const size = useElementSize(panel);
  const scene = useSceneStore(selectDisplayScene);
  const fit = fitView(size.width, size.height, imageAspect(scene), globalThis.devicePixelRatio || 1);
  const live = useLivePreview({ scene, width: fit.pixels.width, height: fit.pixels.height, onFieldErrors, socketFactory, decodeImage });
  const { problem } = live;
  return (
    <div className="preview3d__viewport live-view" ref={panel} data-testid="ray-traced-view">
      <LiveCanvas canvasRef={live.canvasRef} box={fit.box} frame={live.frame} sentRevision={live.sentRevision} connection={live.connection} onReconnect={live.reconnect} />
      {problem && (
        <div className="live-view__problem">
          {problem.status === 400 ? (
            <ErrorSummary title={problem.title} detail={problem.detail} errors={problem.errors} {...fieldWordsOf(scene)} />
          ) : (
            <RenderNotice error={new JobApiError(problem)} job={null} />
          )}
        </div>
      )}
    </div>
  );
}
