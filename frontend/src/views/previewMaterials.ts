/** three.js materials for the preview's material descriptors, shared by equal descriptors. */
import {
  Color,
  DoubleSide,
  FrontSide,
  MeshBasicMaterial,
  MeshLambertMaterial,
  MeshPhongMaterial,
  MeshPhysicalMaterial,
  MeshStandardMaterial,
  type Material,
  type Texture,
} from 'three';
import type { MaterialDescriptor } from '../model/toThree';
import type { TextureCache } from './previewTextures';

/**
 * Builds the three.js material of a descriptor (colours are sRGB, converted to linear); `map` its
 * texture, if any; `flat`: each triangle shaded with its face normal (a mesh without normals).
 */
export function createMaterial(d: MaterialDescriptor, doubleSided: boolean, map: Texture | null = null, flat = false): Material {
  const material = untexturedMaterial(d, doubleSided);
  if (map) Object.assign(material, { map });
  if (flat && !(material instanceof MeshBasicMaterial)) Object.assign(material, { flatShading: true });
  return material;
}

function untexturedMaterial(d: MaterialDescriptor, doubleSided: boolean): Material {
  const side = doubleSided ? DoubleSide : FrontSide;
  const color = new Color(d.color);
  switch (d.kind) {
    case 'basic':
      return new MeshBasicMaterial({ color, side });
    case 'lambert':
      return new MeshLambertMaterial({ color: color.multiplyScalar(d.diffuse), side });
    case 'phong':
      return new MeshPhongMaterial({
        color: color.multiplyScalar(d.diffuse),
        specular: new Color(1, 1, 1).multiplyScalar(d.specular),
        shininess: d.shininess,
        side,
      });
    case 'standard':
      return new MeshStandardMaterial({ color, metalness: d.metalness, roughness: d.roughness, side });
    case 'physical':
      return new MeshPhysicalMaterial({
        color,
        transmission: d.transmission,
        ior: d.ior,
        roughness: d.roughness,
        // a solid of glass: light bends through its whole depth (in the shared geometries' own units,
        // the unit sphere's diameter); with 1 the sphere barely bent what was behind it
        thickness: 2,
        attenuationColor: color,
        specularIntensity: 1,
        side,
      });
  }
}

/** Keeps one material per distinct descriptor; {@link sweep} disposes those no longer used. */
export class MaterialCache {
  private readonly live = new Map<string, Material>();
  private used = new Set<string>();

  /** @param textures makes each textured material's texture (none: textures are left out) */
  constructor(private readonly textures: TextureCache | null = null) {}

  /** The material of `d`, seen from both sides with `doubleSided`, shaded per triangle with `flat`. */
  get(d: MaterialDescriptor, doubleSided: boolean, flat = false): Material {
    const key = JSON.stringify([d, doubleSided, flat]);
    this.used.add(key);
    let material = this.live.get(key);
    if (!material) {
      material = createMaterial(d, doubleSided, d.texture && this.textures ? this.textures.create(d.texture) : null, flat);
      this.live.set(key, material);
    }
    return material;
  }

  /** Disposes every material not asked for since the last sweep. */
  sweep(): void {
    for (const [key, material] of this.live) {
      if (!this.used.has(key)) {
        disposeWithMap(material);
        this.live.delete(key);
      }
    }
    this.used = new Set();
  }

  dispose(): void {
    for (const material of this.live.values()) disposeWithMap(material);
    this.live.clear();
  }
}

/** A material and its own texture copy go together. */
function disposeWithMap(material: Material): void {
  (material as Material & { map?: Texture | null }).map?.dispose();
  material.dispose();
}
