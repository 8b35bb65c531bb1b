import { formatMillis, toPercent } from './format';
import type { RenderPhase } from './useRenderJob';

/** Props of {@link RenderProgress}. */
export interface RenderProgressProps {
  phase: RenderPhase;
  /** Fraction done, 0..1. */
  progress: number;
  elapsedMillis: number;
}

const LABELS: Record<RenderPhase, string> = {
  idle: '',
  starting: 'Sending the scene',
  queued: 'Queued',
  running: 'Rendering',
  done: 'Done',
  failed: 'Failed',
  cancelled: 'Cancelled',
};

/** A progress bar (0..100 for assistive technology) with the percentage and elapsed time. */
export function RenderProgress({ phase, progress, elapsedMillis }: RenderProgressProps) {
  const percent = toPercent(phase === 'done' ? 1 : progress);
  const text = `${percent}% · ${formatMillis(elapsedMillis)}`;
  return (
    <div
      className="render-progress"
      role="progressbar"
      aria-label="Render progress"
      aria-valuemin={0}
      aria-valuemax={100}
      aria-valuenow={percent}
      aria-valuetext={LABELS[phase] ? `${LABELS[phase]}: ${text}` : text}
      data-testid="render-progress"
    >
      <div className="render-progress__track" aria-hidden="true">
        <div className="render-progress__fill" style={{ width: `${percent}%` }} />
      </div>
      <span className="render-progress__text">
        {LABELS[phase] && `${LABELS[phase]} · `}
        {text}
      </span>
    </div>
  );
}
