/** Save: downloads the scene as `NAME.json` (the toolbar's Save and the autosave notice's). */
import { sceneFileName, sceneFileText } from '../model/files';
import type { Scene } from '../model/types';

export function downloadScene(scene: Scene): void {
  const url = URL.createObjectURL(new Blob([sceneFileText(scene)], { type: 'application/json' }));
  const link = document.createElement('a');
  link.href = url;
  link.download = sceneFileName(scene);
  link.click();
  setTimeout(() => URL.revokeObjectURL(url), 1000);
}
