/** Editing a material's texture (pure): none, a checker, or an uploaded image. */
import type { CheckerTexture, Material, Texture, TextureType } from './types';

/** The checker a material gets when its texture is first set to checker. */
export const DEFAULT_CHECKER: CheckerTexture = { type: 'checker', colors: ['#ffffff', '#202020'], size: 0.5 };

/**
 * The material with its texture set to a kind: none drops it; checker keeps a checker it has, or
 * takes the default one; image keeps an image it has, and otherwise is not possible without a file
 * (null: the caller asks for one).
 */
export function withTextureType(material: Material, type: TextureType | 'none'): Material | null {
  const { texture, ...rest } = material;
  if (type === 'none') return rest as Material;
  if (texture?.type === type) return material;
  if (type === 'checker') return { ...rest, texture: structuredClone(DEFAULT_CHECKER) } as Material;
  return null;
}

/** The material with one field of its texture changed (a checker's colour or size, an image's scale). */
export function withTextureField(material: Material, change: (texture: Texture) => Texture): Material {
  return material.texture ? ({ ...material, texture: change(material.texture) } as Material) : material;
}
