/**
 * The asset id of some bytes, as the server computes it: `sha256-` and the 64 lower-case hex
 * digits of their SHA-256 (Web Crypto). The bytes are read in slices, so the caller can show how
 * far reading has got; Web Crypto then digests them in one call (it has no incremental form).
 */

/** What {@link assetIdOf} needs of a file: its size and its slices' bytes (a Blob or File will do). */
export interface ByteSource {
  readonly size: number;
  slice(start: number, end: number): { arrayBuffer(): Promise<ArrayBuffer> };
}

/** Bytes read between two progress reports. */
export const HASH_SLICE_BYTES = 4 * 1024 * 1024;

/** `sha256-<hex>` of the bytes; `onProgress` gets the fraction read (rising, 1 at the end). */
export async function assetIdOf(source: ByteSource, onProgress?: (fraction: number) => void, sliceBytes = HASH_SLICE_BYTES): Promise<string> {
  const bytes = new Uint8Array(source.size);
  for (let start = 0; start < source.size; start += sliceBytes) {
    const end = Math.min(source.size, start + sliceBytes);
    bytes.set(new Uint8Array(await source.slice(start, end).arrayBuffer()), start);
    onProgress?.(end / source.size);
  }
  if (source.size === 0) onProgress?.(1);
  return hexId(await crypto.subtle.digest('SHA-256', bytes));
}

/** `sha256-` and the hex of a digest. */
export function hexId(digest: ArrayBuffer): string {
  return `sha256-${Array.from(new Uint8Array(digest), (b) => b.toString(16).padStart(2, '0')).join('')}`;
}
