/**
 * What the 3D preview draws of a scene (no renderer, no React): the meshes, the lights
 * ({@link PreviewLights}), the selection's boxes and the render camera's frustum, with the shared
 * geometries and materials, the reflection probes and what a click can pick. Each mesh and light is
 * kept by its object's stable id and changed in place; an update creates only what is new and
 * disposes only what is gone ({@link planMeshes}, `planLights`), so a drag step builds nothing.
 */
import {
  AmbientLight,
  BoxGeometry,
  BoxHelper,
  CameraHelper,
  Group,
  Mesh,
  MeshBasicMaterial,
  PerspectiveCamera,
  PlaneGeometry,
  SphereGeometry,
  type BufferGeometry,
  type Material,
  type Object3D,
  type Scene,
  type WebGLRenderer,
} from 'three';
import type { DragTarget } from '../model/selection';
import { flatShaded } from '../model/meshGeometry';
import { applyRenderCamera, type MeshDescriptor, type ThreeSceneDescriptor } from '../model/toThree';
import { MeshGeometryCache } from './previewGeometries';
import { loadAssetBytes } from '../hooks/useMeshes';
import { gltfModel } from './gltfModels';
import { PreviewLights } from './previewLights';
import { MaterialCache } from './previewMaterials';
import { TextureCache } from './previewTextures';
import { meshBuild, planMeshes, type MeshBuild } from './previewReconcile';
import type { DrawProgress } from './firstDraw';
import { ReflectionProbes } from './reflectionProbes';

const SELECTED = 0x4ea1ff;

interface MeshEntry {
  readonly build: MeshBuild;
  readonly mesh: Mesh;
  /** The selection's box, while selected. */
  box: BoxHelper | null;
}

export class PreviewContent {
  /** Everything drawn; the engine adds it to its scene. */
  readonly root = new Group();
  /** What a click can pick: the lights' markers first (a light inside an object is still found), then the meshes. */
  readonly pickables: Mesh[] = [];
  /** What reflections leave out: the markers and helpers. */
  readonly helpers: Object3D[] = [];
  private readonly textures: TextureCache;
  private readonly materials: MaterialCache;
  /** What a glTF model's box is drawn with: nothing (the model inside it is what shows; the box is what a click picks). */
  private readonly hidden = new MeshBasicMaterial({ visible: false });
  private readonly meshGeometries = new MeshGeometryCache();
  private readonly geometries = {
    sphere: new SphereGeometry(1, 48, 32), box: new BoxGeometry(1, 1, 1), plane: new PlaneGeometry(1, 1, 64, 64), marker: new SphereGeometry(1, 16, 12), panel: new PlaneGeometry(1, 1),
  };
  private readonly probes = new ReflectionProbes();
  private readonly ambient = new AmbientLight(0xffffff, 0);
  private readonly meshes = new Map<string, MeshEntry>();
  private readonly lights = new PreviewLights(this.root, this.geometries);
  private frustum: CameraHelper | null = null;

  /** @param onAsync called when something arrives after an update (an image texture's pixels): draw again */
  constructor(onAsync: () => void = () => {}) {
    this.textures = new TextureCache((id) => loadAssetBytes(id), onAsync);
    this.materials = new MaterialCache(this.textures);
    this.root.add(this.ambient);
  }

  /** Shows `d`; with `frustum`, the render camera's frustum too (the orbit view). */
  update(d: ThreeSceneDescriptor, frustum: boolean): void {
    this.pickables.length = 0;
    this.helpers.length = 0;
    this.ambient.intensity = d.ambient;
    const meshes = planMeshes(this.meshes, d.meshes);
    for (const key of meshes.remove) this.removeMesh(key);
    for (const step of meshes.steps) {
      if (step.action === 'create') this.meshes.set(step.key, this.createMesh(step.next));
      this.placeMesh(this.meshes.get(step.key)!, step.next, d);
    }
    // each kept mesh asked for its geometry and material again: the sweeps free only what none uses
    this.materials.sweep();
    this.meshGeometries.sweep();
    this.probes.sweep();
    this.lights.update(d, this.pickables, this.helpers);
    this.showFrustum(frustum ? d : null);
  }

  /** True while a large mesh just added is not yet drawn whole ({@link drawNextPart}). */
  get growing(): boolean {
    return this.meshGeometries.draws.active;
  }

  /** Draws the next part of each large mesh just added; true when one of them drew its first part. */
  drawNextPart(): boolean {
    return this.meshGeometries.draws.step();
  }

  /** How much of the large meshes just added is drawn, or null when each is whole. */
  drawProgress(): DrawProgress | null {
    return this.meshGeometries.draws.progress();
  }

  /** Takes every reflection probe's cube map, with the helpers and `hide` (the handles) left out. */
  takeReflections(renderer: WebGLRenderer, scene: Scene, hide: Object3D[]): void {
    this.probes.update(renderer, scene, [...this.helpers, ...hide]);
  }

  dispose(): void {
    [...this.meshes.keys()].forEach((key) => this.removeMesh(key));
    this.lights.dispose();
    this.showFrustum(null);
    this.probes.clear();
    this.materials.dispose();
    this.textures.dispose();
    this.hidden.dispose();
    this.meshGeometries.dispose();
    Object.values(this.geometries).forEach((g) => g.dispose());
  }

  private createMesh(m: MeshDescriptor): MeshEntry {
    const mesh = new Mesh(this.geometryOf(m), this.materialOf(m));
    mesh.castShadow = m.geometry !== 'plane';
    mesh.receiveShadow = true;
    if (m.geometry === 'gltf') {
      // a copy of the model read once per asset (it shares the model's geometries and materials)
      const model = gltfModel(m.asset!)?.clone(true);
      // it casts shadows on the rest; it receives none, as its often open, double-sided surfaces
      // would shadow themselves in stripes (three's shadow maps have no bias here: see createLight)
      model?.traverse((o) => {
        o.castShadow = true;
      });
      if (model) mesh.add(model);
    }
    this.root.add(mesh);
    return { build: meshBuild(m), mesh, box: null };
  }

  /** The geometry of `m` (the same for as long as its build is). */
  private geometryOf(m: MeshDescriptor): BufferGeometry {
    return m.geometry === 'mesh' || m.geometry === 'gltf' ? this.meshGeometries.get(m.mesh!) : this.geometries[m.geometry];
  }

  private materialOf(m: MeshDescriptor): Material {
    if (m.geometry === 'gltf') return this.hidden;
    // Planes and meshes (which may be open) are seen from both sides; a mesh without normals is flat.
    return this.materials.get(m.material, m.geometry === 'plane' || m.geometry === 'mesh', m.geometry === 'mesh' && flatShaded(m.mesh!));
  }

  /** Puts a mesh where `m` says, in its material (asked of the caches each time, which keeps them in use). */
  private placeMesh(entry: MeshEntry, m: MeshDescriptor, d: ThreeSceneDescriptor): void {
    const { mesh } = entry;
    mesh.geometry = this.geometryOf(m);
    mesh.material = this.materialOf(m);
    mesh.position.set(...m.position);
    mesh.scale.set(...m.scale);
    if (m.geometry === 'plane') mesh.quaternion.set(...m.quaternion);
    else mesh.rotation.set(m.rotation[0], m.rotation[1], m.rotation[2], 'XYZ');
    if (m.geometry !== 'gltf' && (m.material.kind === 'standard' || m.material.kind === 'physical')) {
      mesh.updateMatrixWorld();
      this.probes.add(mesh, m.position, d.camera.near, d.camera.far);
    }
    // a new target each time: the one a click handed to the store stays as it was
    mesh.userData.target = { kind: 'object', index: m.index } satisfies DragTarget;
    this.pickables.push(mesh);
    const boxed = m.selected && m.geometry !== 'plane';
    if (boxed && !entry.box) entry.box = this.addHelper(new BoxHelper(mesh, SELECTED));
    else if (boxed) entry.box!.update();
    else if (entry.box) entry.box = dropHelper(entry.box);
    if (entry.box) this.helpers.push(entry.box);
  }

  private removeMesh(key: string): void {
    const entry = this.meshes.get(key)!;
    entry.mesh.removeFromParent();
    if (entry.box) dropHelper(entry.box);
    this.meshes.delete(key);
  }

  /** The render camera's frustum as `d` frames it (kept from update to update), or none. */
  private showFrustum(d: ThreeSceneDescriptor | null): void {
    if (!d) {
      if (this.frustum) this.frustum = dropHelper(this.frustum);
      return;
    }
    const c = d.camera;
    const camera = applyRenderCamera((this.frustum?.camera as PerspectiveCamera) ?? new PerspectiveCamera(), { ...c, far: Math.hypot(...c.position.map((p, i) => p - c.lookAt[i])) });
    if (this.frustum) this.frustum.update();
    else this.frustum = this.addHelper(new CameraHelper(camera));
    this.helpers.push(this.frustum);
  }

  private addHelper<T extends BoxHelper | CameraHelper>(helper: T): T {
    this.root.add(helper);
    return helper;
  }
}

function dropHelper(helper: BoxHelper | CameraHelper): null {
  helper.removeFromParent();
  helper.dispose();
  return null;
}
