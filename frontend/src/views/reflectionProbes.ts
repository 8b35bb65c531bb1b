/**
 * Reflections of the scene itself for the preview's mirrors, metals and glass: a cube camera at
 * each reflective object (at most {@link MAX_PROBES}; the rest reflect nothing but the
 * background), taken with that object hidden just before each frame. It replaces the made-up
 * room the preview used to reflect, which the render never shows.
 */
import { CubeCamera, HalfFloatType, type Material, type Mesh, type Scene, type WebGLRenderer, WebGLCubeRenderTarget } from 'three';

/** Cube maps taken per frame (six renders each): four keep a drag fluid in software WebGL. */
export const MAX_PROBES = 4;
const SIZE = 128;

interface Probe {
  mesh: Mesh;
  camera: CubeCamera;
  target: WebGLCubeRenderTarget;
  material: Material;
}

export class ReflectionProbes {
  private probes: Probe[] = [];

  /**
   * Gives a reflective mesh its own copy of its material with a cube map of the scene, seen from
   * `at` (its centre; for a plane, its point nearest the camera). Returns false past the limit.
   */
  add(mesh: Mesh, at: [number, number, number], near: number, far: number): boolean {
    if (this.probes.length >= MAX_PROBES) return false;
    const target = new WebGLCubeRenderTarget(SIZE, { type: HalfFloatType });
    const camera = new CubeCamera(near, far, target);
    camera.position.set(...at);
    const material = (mesh.material as Material).clone() as Material & { envMap: unknown; needsUpdate: boolean };
    material.envMap = target.texture;
    material.needsUpdate = true;
    mesh.material = material;
    this.probes.push({ mesh, camera, target, material });
    return true;
  }

  /** Takes every cube map: the object and `hide` (helpers, handles) out of its own reflection. */
  update(renderer: WebGLRenderer, scene: Scene, hide: { visible: boolean }[]): void {
    if (this.probes.length === 0) return;
    const shown = hide.map((o) => o.visible);
    hide.forEach((o) => (o.visible = false));
    for (const p of this.probes) {
      p.mesh.visible = false;
      p.camera.update(renderer, scene);
      p.mesh.visible = true;
    }
    hide.forEach((o, i) => (o.visible = shown[i]));
  }

  /** Frees every cube map and material copy (before the content is rebuilt). */
  clear(): void {
    for (const p of this.probes) {
      p.target.dispose();
      p.material.dispose();
    }
    this.probes = [];
  }
}
