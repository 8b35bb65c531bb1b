/// <reference lib="webworker" />
/**
 * Hashes a file off the page's thread: receives `{ file }`, posts `{ progress }` as it reads and
 * then `{ id }` (or `{ error }`).
 */
import { assetIdOf } from '../model/assetHash';

self.onmessage = async (event: MessageEvent<{ file: Blob }>) => {
  try {
    const id = await assetIdOf(event.data.file, (progress) => self.postMessage({ progress }));
    self.postMessage({ id });
  } catch (error) {
    self.postMessage({ error: error instanceof Error ? error.message : String(error) });
  }
};
