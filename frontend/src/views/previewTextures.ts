/**
 * three.js textures for the preview's texture descriptors: a checker as a 2x2 DataTexture of its
 * colours (mip-mapped, so it fades to their mean towards the horizon instead of shimmering), an
 * image from its asset's bytes (this browser's copy or the server's), read once per asset. Each
 * material gets its own copy of the texture (its own repeat and offset) sharing the pixels.
 */
import { DataTexture, LinearMipmapLinearFilter, NearestFilter, RepeatWrapping, RGBAFormat, SRGBColorSpace, Texture, Color } from 'three';
import type { TextureDescriptor } from '../model/toThree';

/** Loads an image asset's bytes. */
export type AssetBytesLoader = (id: string) => Promise<ArrayBuffer>;

export class TextureCache {
  private readonly checkers = new Map<string, DataTexture>();
  private readonly images = new Map<string, Texture>();
  /** The copies of each image (each needs telling when its pixels arrive). */
  private readonly copies = new Map<string, Set<Texture>>();

  /**
   * @param loadBytes where image assets come from
   * @param onLoaded called when an image's pixels arrive (the preview draws again)
   */
  constructor(private readonly loadBytes: AssetBytesLoader, private readonly onLoaded: () => void) {}

  /** A new texture of `d` (the caller disposes it with its material). */
  create(d: TextureDescriptor): Texture {
    const base = d.kind === 'checker' ? this.checker(d.colors) : this.image(d.asset);
    const texture = base.clone();
    texture.wrapS = texture.wrapT = RepeatWrapping;
    texture.repeat.set(...d.repeat);
    texture.offset.set(...d.offset);
    texture.needsUpdate = base.image !== undefined && base.image !== null;
    if (d.kind === 'image') {
      const copies = this.copies.get(d.asset) ?? new Set();
      copies.add(texture);
      this.copies.set(d.asset, copies);
      texture.addEventListener('dispose', () => copies.delete(texture));
    }
    return texture;
  }

  dispose(): void {
    for (const t of [...this.checkers.values(), ...this.images.values()]) t.dispose();
    this.checkers.clear();
    this.images.clear();
  }

  private checker(colors: [string, string]): DataTexture {
    const key = colors.join();
    let texture = this.checkers.get(key);
    if (!texture) {
      const [a, b] = colors.map((c) => new Color(c).getHex(SRGBColorSpace));
      const rgba = (hex: number) => [(hex >> 16) & 255, (hex >> 8) & 255, hex & 255, 255];
      texture = new DataTexture(new Uint8Array([...rgba(a), ...rgba(b), ...rgba(b), ...rgba(a)]), 2, 2, RGBAFormat);
      texture.colorSpace = SRGBColorSpace;
      texture.magFilter = NearestFilter;
      texture.minFilter = LinearMipmapLinearFilter;
      texture.generateMipmaps = true;
      texture.needsUpdate = true;
      this.checkers.set(key, texture);
    }
    return texture;
  }

  private image(asset: string): Texture {
    let texture = this.images.get(asset);
    if (!texture) {
      const created = new Texture();
      created.colorSpace = SRGBColorSpace;
      texture = created;
      this.images.set(asset, created);
      void this.loadBytes(asset)
        .then((bytes) => decode(bytes))
        .then((image) => {
          created.image = image;
          created.needsUpdate = true;
          for (const copy of this.copies.get(asset) ?? []) {
            copy.image = image;
            copy.needsUpdate = true;
          }
          this.onLoaded();
        })
        .catch(() => undefined); // the material keeps its colour; the server's render names a bad asset
    }
    return texture;
  }
}

function decode(bytes: ArrayBuffer): Promise<HTMLImageElement> {
  return new Promise((resolve, reject) => {
    const url = URL.createObjectURL(new Blob([bytes]));
    const image = new Image();
    image.onload = () => {
      URL.revokeObjectURL(url);
      resolve(image);
    };
    image.onerror = () => {
      URL.revokeObjectURL(url);
      reject(new Error('the image cannot be decoded'));
    };
    image.src = url;
  });
}
