import { formatMillis } from '../render/format';
import type { FrameHeader } from './protocol';

/**
 * The status line under a live frame: "pass 4 · 1 spp · 640x480 · 38 ms" while refining,
 * "final · 16 spp · 640x480 · 1.2 s" for the revision's last frame.
 */
export function describeFrame(frame: FrameHeader): string {
  const stage = frame.final ? 'final' : `pass ${frame.pass}`;
  return `${stage} · ${frame.samplesPerPixel} spp · ${frame.width}x${frame.height} · ${formatMillis(frame.millis)}`;
}
