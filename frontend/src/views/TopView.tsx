import { OrthoView } from './OrthoView';

/** The plan view from above: x to the right, z down the screen (towards the viewer). */
export function TopView() {
  return <OrthoView kind="top" title="Top view" axesHint="x → right, z ↓ (towards the camera side)" />;
}
