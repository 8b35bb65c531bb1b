/**
 * What the 3D preview draws of a scene (no renderer, no React): the meshes, lights and their
 * markers, the selection's boxes and the render camera's frustum, with the shared geometries and
 * materials, the reflection probes and what a click can pick.
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
  PointLight,
  SphereGeometry,
  type Object3D,
  type Scene,
  type WebGLRenderer,
} from 'three';
import type { DragTarget } from '../model/selection';
import { applyRenderCamera, type ThreeSceneDescriptor } from '../model/toThree';
import { MeshGeometryCache } from './previewGeometries';
import { MaterialCache } from './previewMaterials';
import { MAX_SHADOW_LIGHTS } from './previewReconcile';
import { ReflectionProbes } from './reflectionProbes';

const SELECTED = 0x4ea1ff;

export class PreviewContent {
  /** Everything drawn; the engine adds it to its scene. */
  readonly root = new Group();
  /** What a click can pick: the lights' markers first (a light inside an object is still found), then the meshes. */
  readonly pickables: Mesh[] = [];
  /** What reflections leave out: the markers and helpers. */
  readonly helpers: Object3D[] = [];
  private readonly materials = new MaterialCache();
  private readonly meshGeometries = new MeshGeometryCache();
  private readonly geometries = { sphere: new SphereGeometry(1, 48, 32), box: new BoxGeometry(1, 1, 1), plane: new PlaneGeometry(1, 1, 64, 64), marker: new SphereGeometry(1, 16, 12) };
  private readonly disposables: { dispose(): void }[] = [];
  private readonly probes = new ReflectionProbes();

  /** Shows `d`; with `frustum`, the render camera's frustum too (the orbit view). */
  update(d: ThreeSceneDescriptor, frustum: boolean): void {
    for (const item of this.disposables.splice(0)) item.dispose();
    this.probes.clear();
    this.root.clear();
    this.pickables.length = 0;
    this.helpers.length = 0;
    this.root.add(new AmbientLight(0xffffff, d.ambient));
    for (const m of d.meshes) {
      const geometry = m.geometry === 'mesh' ? this.meshGeometries.get(m.mesh!) : this.geometries[m.geometry];
      // Planes and meshes (which may be open) are seen from both sides.
      const mesh = new Mesh(geometry, this.materials.get(m.material, m.geometry === 'plane' || m.geometry === 'mesh'));
      mesh.position.set(...m.position);
      mesh.scale.set(...m.scale);
      if (m.geometry === 'plane') mesh.quaternion.set(...m.quaternion);
      else mesh.rotation.set(m.rotation[0], m.rotation[1], m.rotation[2], 'XYZ');
      mesh.castShadow = m.geometry !== 'plane';
      mesh.receiveShadow = true;
      if (m.material.kind === 'standard' || m.material.kind === 'physical') {
        mesh.updateMatrixWorld();
        this.probes.add(mesh, m.position, d.camera.near, d.camera.far);
      }
      mesh.userData.target = { kind: 'object', index: m.index } satisfies DragTarget;
      this.pickables.push(mesh);
      this.root.add(mesh);
      if (m.selected && m.geometry !== 'plane') this.addHelper(new BoxHelper(mesh, SELECTED));
    }
    this.materials.sweep();
    this.meshGeometries.sweep();
    for (const l of d.lights) {
      const light = new PointLight(l.color, l.intensity, 0, l.decay);
      light.position.set(...l.position);
      if (l.index < MAX_SHADOW_LIGHTS) {
        light.castShadow = true;
        light.shadow.mapSize.set(1024, 1024);
        light.shadow.camera.near = Math.max(d.camera.near, d.extent * 1e-4);
        light.shadow.camera.far = d.camera.far;
        // no bias: with three 0.187 a point light's shadow vanished with a bias of -0.0005 (measured)
        this.disposables.push({ dispose: () => light.shadow.dispose() });
      }
      this.root.add(light);
      const markerMaterial = new MeshBasicMaterial({ color: l.selected ? SELECTED : l.color });
      this.disposables.push(markerMaterial);
      const marker = new Mesh(this.geometries.marker, markerMaterial);
      this.helpers.push(marker);
      marker.position.set(...l.position);
      marker.scale.setScalar(d.extent * (l.selected ? 0.008 : 0.005));
      marker.userData.target = { kind: 'light', index: l.index } satisfies DragTarget;
      this.pickables.unshift(marker);
      this.root.add(marker);
    }
    if (frustum) {
      const camera = applyRenderCamera(new PerspectiveCamera(), { ...d.camera, far: Math.hypot(...d.camera.position.map((p, i) => p - d.camera.lookAt[i])) });
      this.addHelper(new CameraHelper(camera));
    }
  }

  /** Takes every reflection probe's cube map, with the helpers and `hide` (the handles) left out. */
  takeReflections(renderer: WebGLRenderer, scene: Scene, hide: Object3D[]): void {
    this.probes.update(renderer, scene, [...this.helpers, ...hide]);
  }

  dispose(): void {
    this.probes.clear();
    for (const item of this.disposables.splice(0)) item.dispose();
    this.materials.dispose();
    this.meshGeometries.dispose();
    Object.values(this.geometries).forEach((g) => g.dispose());
    this.root.clear();
  }

  private addHelper(helper: BoxHelper | CameraHelper): void {
    this.helpers.push(helper);
    this.root.add(helper);
    this.disposables.push(helper);
  }
}
