import { OrthoView } from './OrthoView';

/** The elevation seen from +z: x to the right, y up. */
export function SideView() {
  return <OrthoView kind="side" title="Side view" axesHint="x → right, y ↑ up (seen from +z)" />;
}
