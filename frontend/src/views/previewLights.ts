/**
 * The 3D preview's lights (no renderer, no React), kept by each light's stable id and changed in
 * place ({@link planLights}): a drag step builds nothing.
 *
 * - A point light is a three.js PointLight with a small marker sphere (what a click picks); with a
 *   radius, also its glowing sphere of that radius, as camera and mirrors see it in the render.
 * - An area light is a RectAreaLight (RectAreaLightUniformsLib.init() runs once, for the first one),
 *   placed and aimed by three.js's own lookAt, with its glowing rectangle and a marker. Only
 *   three.js's physically based materials (metal, mirror, glass) take a RectAreaLight's light, so a
 *   spot light from its centre over its front half-space (a cosine-like fade, as a small area light
 *   lights) lights the others (chalk, plastic); the first {@link MAX_SHADOW_LIGHTS} lights cast
 *   shadows (an area light's through that spot, hard where the render's are soft). Two-sided: the
 *   same again facing back.
 */
import {
  BackSide,
  DoubleSide,
  Mesh,
  MeshBasicMaterial,
  PointLight,
  RectAreaLight,
  SpotLight,
  type Group,
  type Object3D,
  type PlaneGeometry,
  type SphereGeometry,
} from 'three';
import { RectAreaLightUniformsLib } from 'three/examples/jsm/lights/RectAreaLightUniformsLib.js';
import type { DragTarget } from '../model/selection';
import type { AreaLightDescriptor, LightDescriptor, PointLightDescriptor, ThreeSceneDescriptor } from '../model/toThree';
import { castsShadow, lightBuild, planLights, type LightBuild } from './previewReconcile';

const SELECTED = 0x4ea1ff;

/** The shared geometries the lights are drawn with (the content owns and disposes them). */
export interface LightGeometries {
  /** Radius 1: the markers and a sphere light's glow. */
  marker: SphereGeometry;
  /** 1 x 1 in its x-y plane, facing +z: an area light's glowing rectangle. */
  panel: PlaneGeometry;
}

/** One face of an area light: its RectAreaLight and the spot that lights what a RectAreaLight cannot. */
interface AreaFace {
  readonly rect: RectAreaLight;
  readonly spot: SpotLight;
}

interface LightEntry {
  readonly build: LightBuild;
  /** A point light's PointLight, none for an area light. */
  readonly point: PointLight | null;
  /** An area light's faces (two when two-sided), none for a point light. */
  readonly faces: AreaFace[];
  /** The small sphere that shows where the light is, and is picked. */
  readonly marker: Mesh<SphereGeometry, MeshBasicMaterial>;
  /** What the render shows of the light itself: a sphere light's sphere, an area light's rectangle. */
  readonly glow: Mesh<SphereGeometry | PlaneGeometry, MeshBasicMaterial>;
}

let areaLightsReady = false;

/** Loads the tables RectAreaLight shades with, once per page. */
function readyAreaLights(): void {
  if (areaLightsReady) return;
  RectAreaLightUniformsLib.init();
  areaLightsReady = true;
}

export class PreviewLights {
  private readonly lights = new Map<string, LightEntry>();

  constructor(
    private readonly root: Group,
    private readonly geometries: LightGeometries,
  ) {}

  /** Shows the lights of `d`; puts their markers first in `pickables` (then glows) and the markers in `helpers`. */
  update(d: ThreeSceneDescriptor, pickables: Mesh[], helpers: Object3D[]): void {
    const plan = planLights(this.lights, d.lights);
    for (const key of plan.remove) this.remove(key);
    const markers: Mesh[] = [];
    const glows: Mesh[] = [];
    for (const step of plan.steps) {
      if (step.action === 'create') this.lights.set(step.key, this.create(step.next));
      const entry = this.lights.get(step.key)!;
      this.place(entry, step.next, d);
      markers.push(entry.marker);
      if (entry.glow.visible) glows.push(entry.glow);
      helpers.push(entry.marker);
    }
    pickables.unshift(...markers, ...glows);
  }

  dispose(): void {
    [...this.lights.keys()].forEach((key) => this.remove(key));
  }

  private create(l: LightDescriptor): LightEntry {
    const build = lightBuild(l);
    const marker = new Mesh(this.geometries.marker, new MeshBasicMaterial());
    if (l.kind === 'point') {
      const point = new PointLight();
      point.castShadow = castsShadow(l);
      // no bias: with three 0.187 a point light's shadow vanished with a bias of -0.0005 (measured)
      point.shadow.mapSize.set(1024, 1024);
      const glow = new Mesh(this.geometries.marker, new MeshBasicMaterial());
      this.root.add(point, marker, glow);
      return { build, point, faces: [], marker, glow };
    }
    readyAreaLights();
    const faces = Array.from({ length: l.twoSided ? 2 : 1 }, (_, k) => {
      const face = { rect: new RectAreaLight(), spot: new SpotLight() };
      face.spot.angle = Math.PI / 2;
      face.spot.penumbra = 1;
      face.spot.castShadow = castsShadow(l) && k === 0;
      face.spot.shadow.mapSize.set(1024, 1024);
      this.root.add(face.rect, face.spot, face.spot.target);
      return face;
    });
    // the rectangle emits from its front, three's -z: a plane facing +z shows it from its back
    const glow = new Mesh(this.geometries.panel, new MeshBasicMaterial({ side: l.twoSided ? DoubleSide : BackSide }));
    this.root.add(marker, glow);
    return { build, point: null, faces, marker, glow };
  }

  private place(entry: LightEntry, l: LightDescriptor, d: ThreeSceneDescriptor): void {
    const { marker, glow } = entry;
    if (l.kind === 'point') this.placePoint(entry, l, d);
    else this.placeArea(entry, l, d);
    marker.material.color.set(l.selected ? SELECTED : l.color);
    marker.position.set(...l.position);
    marker.scale.setScalar(d.extent * (l.selected ? 0.008 : 0.005));
    glow.material.color.set(l.color);
    // a new target each time: the one a click handed to the store stays as it was
    marker.userData.target = { kind: 'light', index: l.index } satisfies DragTarget;
    glow.userData.target = { kind: 'light', index: l.index } satisfies DragTarget;
  }

  private placePoint({ point, glow }: LightEntry, l: PointLightDescriptor, d: ThreeSceneDescriptor): void {
    point!.color.set(l.color);
    point!.intensity = l.intensity;
    point!.decay = l.decay;
    point!.position.set(...l.position);
    if (point!.castShadow) fitShadow(point!, d);
    glow.visible = l.radius > 0;
    glow.position.set(...l.position);
    glow.scale.setScalar(l.radius || 1);
  }

  private placeArea({ faces, glow }: LightEntry, l: AreaLightDescriptor, d: ThreeSceneDescriptor): void {
    faces.forEach(({ rect, spot }, k) => {
      // the back face looks at the aim mirrored through the light
      const aim = k === 0 ? l.lookAt : l.lookAt.map((a, i) => 2 * l.position[i] - a);
      rect.color.set(l.color);
      rect.intensity = l.luminance;
      rect.width = l.width;
      rect.height = l.height;
      rect.position.set(...l.position);
      rect.lookAt(aim[0], aim[1], aim[2]);
      spot.color.set(l.color);
      spot.intensity = l.intensity;
      spot.decay = l.decay;
      spot.position.set(...l.position);
      spot.target.position.set(aim[0], aim[1], aim[2]);
      spot.target.updateMatrixWorld();
      if (spot.castShadow) fitShadow(spot, d);
    });
    glow.visible = true;
    glow.position.set(...l.position);
    glow.quaternion.copy(faces[0].rect.quaternion);
    glow.scale.set(l.width, l.height, 1);
  }

  /** A light's shadow map, its marker's and glow's materials go with it. */
  private remove(key: string): void {
    const { point, faces, marker, glow } = this.lights.get(key)!;
    for (const light of [point, ...faces.flatMap((f) => [f.rect, f.spot])]) {
      light?.removeFromParent();
      light?.dispose();
    }
    faces.forEach((f) => f.spot.target.removeFromParent());
    for (const mesh of [marker, glow]) {
      mesh.removeFromParent();
      mesh.material.dispose();
    }
    this.lights.delete(key);
  }
}

/** Keeps a light's shadow camera on the scene's depth range (three sets it once, when it makes the map). */
function fitShadow(light: PointLight | SpotLight, d: ThreeSceneDescriptor): void {
  const near = Math.max(d.camera.near, d.extent * 1e-4);
  const camera = light.shadow.camera;
  if (camera.near !== near || camera.far !== d.camera.far) {
    camera.near = near;
    camera.far = d.camera.far;
    camera.updateProjectionMatrix();
  }
}
