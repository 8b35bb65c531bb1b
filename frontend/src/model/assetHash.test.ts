import { createHash } from 'node:crypto';
import { describe, expect, it } from 'vitest';
import { assetIdOf } from './assetHash';

describe('assetIdOf', () => {
  it('is sha256- and the hex digest, as the server names the same bytes', async () => {
    expect(await assetIdOf(new Blob(['abc']))).toBe('sha256-ba7816bf8f01cfea414140de5dae2223b00361a396177a9cb410ff61f20015ad');
  });

  it('reads in slices, reporting a rising fraction that ends at 1, and hashes every byte once', async () => {
    const bytes = new Uint8Array(10_000).map((_, i) => (i * 31) % 251);
    const progress: number[] = [];
    const id = await assetIdOf(new Blob([bytes]), (f) => progress.push(f), 3000);
    expect(id).toBe(`sha256-${createHash('sha256').update(bytes).digest('hex')}`);
    expect(progress).toEqual([0.3, 0.6, 0.9, 1]);
  });
});
