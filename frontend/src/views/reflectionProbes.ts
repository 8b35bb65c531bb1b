/**
 * Reflections of the scene itself for the preview's mirrors, metals and glass: a cube camera at
 * each reflective object (at most {@link MAX_PROBES}; the rest reflect nothing but the
 * background), taken with that object hidden just before each frame. It replaces the made-up
 * room the preview used to reflect, which the render never shows. A mesh keeps its probe (cube
 * map and material copy) from one update to the next for as long as it reflects, as the
 * material and geometry caches keep theirs: a drag step allocates nothing on the GPU.
 */
import { CubeCamera, HalfFloatType, type Material, type Mesh, type PerspectiveCamera, type Scene, type WebGLRenderer, WebGLCubeRenderTarget } from 'three';

/** Cube maps taken per frame (six renders each): four keep a drag fluid in software WebGL. */
export const MAX_PROBES = 4;
const SIZE = 128;

interface Probe {
  camera: CubeCamera;
  target: WebGLCubeRenderTarget;
  /** The shared material the copy was made of. */
  base: Material;
  /** The mesh's own copy of `base`, with the cube map. */
  material: Material;
}

export class ReflectionProbes {
  private readonly probes = new Map<Mesh, Probe>();
  private used = new Set<Mesh>();

  /**
   * Gives a reflective mesh, wearing its shared material, its own copy of that material with a cube
   * map of the scene seen from `at` (its centre; for a plane, its point nearest the camera). A mesh
   * that has a probe keeps it, with a new copy only when its shared material changed. Returns
   * false past the limit.
   */
  add(mesh: Mesh, at: [number, number, number], near: number, far: number): boolean {
    if (this.used.size >= MAX_PROBES) return false;
    this.used.add(mesh);
    const base = mesh.material as Material;
    let probe = this.probes.get(mesh);
    if (!probe) {
      const target = new WebGLCubeRenderTarget(SIZE, { type: HalfFloatType });
      probe = { camera: new CubeCamera(near, far, target), target, base, material: copyWith(base, target) };
      this.probes.set(mesh, probe);
    } else if (probe.base !== base) {
      probe.material.dispose();
      probe.base = base;
      probe.material = copyWith(base, probe.target);
    }
    setClip(probe.camera, near, far);
    probe.camera.position.set(...at);
    mesh.material = probe.material;
    return true;
  }

  /** Frees the probes of meshes not given one since the last sweep (gone, no longer reflective, or past the limit). */
  sweep(): void {
    for (const [mesh, probe] of this.probes) {
      if (!this.used.has(mesh)) {
        free(probe);
        this.probes.delete(mesh);
      }
    }
    this.used = new Set();
  }

  /** Takes every cube map: the object and `hide` (helpers, handles) out of its own reflection. */
  update(renderer: WebGLRenderer, scene: Scene, hide: { visible: boolean }[]): void {
    if (this.probes.size === 0) return;
    const shown = hide.map((o) => o.visible);
    hide.forEach((o) => (o.visible = false));
    for (const [mesh, p] of this.probes) {
      mesh.visible = false;
      p.camera.update(renderer, scene);
      mesh.visible = true;
    }
    hide.forEach((o, i) => (o.visible = shown[i]));
  }

  /** Frees every cube map and material copy. */
  clear(): void {
    this.probes.forEach(free);
    this.probes.clear();
    this.used = new Set();
  }
}

function copyWith(base: Material, target: WebGLCubeRenderTarget): Material {
  const material = base.clone() as Material & { envMap: unknown; needsUpdate: boolean };
  material.envMap = target.texture;
  material.needsUpdate = true;
  return material;
}

/** The cube camera's six faces see from `near` to `far` (the scene's depth range may change). */
function setClip(camera: CubeCamera, near: number, far: number): void {
  for (const face of camera.children as PerspectiveCamera[]) {
    if (face.near === near && face.far === far) continue;
    face.near = near;
    face.far = far;
    face.updateProjectionMatrix();
  }
}

function free(probe: Probe): void {
  probe.target.dispose();
  probe.material.dispose();
}
