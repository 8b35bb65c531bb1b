import { describe, expect, it } from 'vitest';
import { DEFAULT_CHECKER, withTextureField, withTextureType } from './textureEdits';
import type { Material } from './types';

const image = { type: 'image' as const, asset: `sha256-${'f'.repeat(64)}`, scale: [2, 2] as [number, number] };

describe('texture edits', () => {
  it('sets none, a default checker, or keeps the texture of the kind asked for', () => {
    const plain: Material = { type: 'plastic', color: '#ff0000' };
    expect(withTextureType(plain, 'checker')).toEqual({ ...plain, texture: DEFAULT_CHECKER });
    const textured: Material = { ...plain, texture: image };
    expect(withTextureType(textured, 'none')).toEqual(plain);
    expect(withTextureType(textured, 'image')).toBe(textured);
    expect(withTextureType(textured, 'checker')).toEqual({ ...plain, texture: DEFAULT_CHECKER });
  });

  it('needs a file for an image where there is none', () => {
    expect(withTextureType({ type: 'chalk' }, 'image')).toBeNull();
  });

  it('changes one field of the texture, leaving the material and the default checker alone', () => {
    const m = withTextureType({ type: 'chalk' }, 'checker')!;
    const bigger = withTextureField(m, (t) => ({ ...t, size: 2 }) as typeof t);
    expect(bigger.texture).toEqual({ ...DEFAULT_CHECKER, size: 2 });
    expect(DEFAULT_CHECKER.size).toBe(0.5);
    expect(withTextureField({ type: 'chalk' }, (t) => t)).toEqual({ type: 'chalk' });
  });
});
