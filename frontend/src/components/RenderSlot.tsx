import type { ComponentType } from 'react';
import type { FetchFn } from '../api/client';
import type { Scene } from '../model/types';
import type { FieldErrors } from './fieldErrors';
import { RenderArea } from './RenderArea';

/** The props both render UIs take. */
interface RenderUiProps {
  scene: Scene;
  onFieldErrors: (errors: FieldErrors) => void;
  fetchFn?: FetchFn;
}

// The render-job panel (src/render/RenderPanel.tsx) is built alongside this editor; it is used
// when present, and the simple render path otherwise, so either build stays green.
const modules = import.meta.glob<{ RenderPanel?: ComponentType<RenderUiProps> }>('../render/RenderPanel.tsx', { eager: true });
const RenderPanel = Object.values(modules)[0]?.RenderPanel;

/** Props of {@link RenderSlot}. */
export type RenderSlotProps = RenderUiProps;

/** The render area under the preview: the job panel when available, else {@link RenderArea}. */
export function RenderSlot(props: RenderSlotProps) {
  return RenderPanel ? <RenderPanel {...props} /> : <RenderArea {...props} />;
}

/** True when the render-job panel is in the build. */
export const HAS_RENDER_PANEL = RenderPanel !== undefined;
