/** Hashes a file in a Web Worker (`hash.worker.ts`); where there are no workers (tests), on this thread. */
import { assetIdOf } from '../model/assetHash';

/** The asset id of `file`, with the fraction read reported to `onProgress`. */
export function hashFile(file: Blob, onProgress?: (fraction: number) => void): Promise<string> {
  if (typeof Worker === 'undefined') return assetIdOf(file, onProgress);
  return new Promise((resolve, reject) => {
    const worker = new Worker(new URL('./hash.worker.ts', import.meta.url), { type: 'module' });
    const done = () => worker.terminate();
    worker.onmessage = (event: MessageEvent<{ progress?: number; id?: string; error?: string }>) => {
      const { progress, id, error } = event.data;
      if (progress !== undefined) onProgress?.(progress);
      if (id !== undefined) {
        done();
        resolve(id);
      }
      if (error !== undefined) {
        done();
        reject(new Error(`Could not hash the file: ${error}`));
      }
    };
    worker.onerror = (event) => {
      done();
      reject(new Error(`Could not hash the file: ${event.message || 'the hashing worker failed'}`));
    };
    worker.postMessage({ file });
  });
}
