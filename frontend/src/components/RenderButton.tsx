/** Props of {@link RenderButton}. */
export interface RenderButtonProps {
  /** True while a render is under way: the button is disabled and the indicator shows. */
  rendering: boolean;
  /** Called when the user asks for a render. */
  onRender: () => void;
}

/** The Render button with its "Rendering…" indicator. */
export function RenderButton({ rendering, onRender }: RenderButtonProps) {
  return (
    <div className="render-bar">
      <button type="button" className="primary" disabled={rendering} onClick={onRender}>
        Render
      </button>
      {rendering && (
        <span className="render-bar__busy" role="status">
          <span className="spinner" aria-hidden="true" />
          Rendering…
        </span>
      )}
    </div>
  );
}
