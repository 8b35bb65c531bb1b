import type { RenderPhase } from './useRenderJob';

/** Props of {@link RenderControls}. */
export interface RenderControlsProps {
  /** Where the current job is; decides which buttons show and which are enabled. */
  phase: RenderPhase;
  /** True after Cancel was pressed, until the job ends. */
  cancelling: boolean;
  /** Starts a render (cancelling one under way first). */
  onRender: () => void;
  /** Stops the render under way. */
  onCancel: () => void;
}

/** The Render button, and a Cancel button while a job is queued or running. */
export function RenderControls({ phase, cancelling, onRender, onCancel }: RenderControlsProps) {
  const active = phase === 'starting' || phase === 'queued' || phase === 'running';
  return (
    <div className="render-controls">
      <button
        type="button"
        className="primary"
        data-testid="render-button"
        disabled={phase === 'starting'}
        onClick={onRender}
        title={active ? 'Stop this render and start again' : undefined}
      >
        Render
      </button>
      {active && (
        <button
          type="button"
          className="secondary"
          data-testid="cancel-button"
          disabled={cancelling}
          onClick={onCancel}
        >
          {cancelling ? 'Cancelling…' : 'Cancel'}
        </button>
      )}
    </div>
  );
}
