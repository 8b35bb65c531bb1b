import { describe, expect, it } from 'vitest';
import { addMesh, addObject } from './edits';
import { meshBounds, parseObj } from './obj';
import { CLEARANCE, floorHeight, placeOnFloor } from './placement';
import { STARTER_SCENE } from './starterScene';
import { TETRAHEDRON_OBJ } from '../test/meshes';
import type { Scene, Sphere, Vec3 } from './types';
import { makeRenderCamera, projectToPixel, sceneToThree } from './toThree';

const last = (scene: Scene) => scene.objects[scene.objects.length - 1];
const flat = (a: Vec3, b: Vec3) => Math.hypot(a[0] - b[0], a[2] - b[2]);

/** The pixel a world point lands on in the scene's render, and whether it is inside the image. */
function inImage(scene: Scene, p: Vec3): boolean {
  const d = sceneToThree(scene);
  const [x, y] = projectToPixel(makeRenderCamera(d.camera), p, 800, 600);
  return x > 0 && x < 800 && y > 0 && y < 600;
}

describe('placement of new objects', () => {
  it('puts a new sphere on the floor, seen by the camera, off the camera target', () => {
    const scene: Scene = { camera: { position: [0, 2, 8], lookAt: [0, 0, 0] }, objects: [] };
    const sphere = last(addObject(scene, 'sphere')) as Sphere;
    expect(sphere.center![1]).toBe(1); // radius 1 resting on y = 0
    expect(flat(sphere.center!, [0, 0, 0])).toBeGreaterThanOrEqual(1 + CLEARANCE);
    expect(inImage(scene, sphere.center!)).toBe(true);
  });

  it('never piles new objects up: ten spheres in a row overlap neither each other nor the target', () => {
    let scene: Scene = { ...STARTER_SCENE };
    for (let i = 0; i < 10; i++) scene = addObject(scene, 'sphere');
    const centres = scene.objects.slice(STARTER_SCENE.objects.length).map((o) => (o as Sphere).center!);
    for (let i = 0; i < centres.length; i++) {
      for (let j = 0; j < i; j++) expect(flat(centres[i], centres[j])).toBeGreaterThanOrEqual(2);
      expect(flat(centres[i], scene.camera!.lookAt!)).toBeGreaterThanOrEqual(1);
    }
    // and the starter's own objects are left room
    const placed = centres[0];
    for (const o of STARTER_SCENE.objects) if (o.type === 'sphere') expect(flat(placed, o.center!)).toBeGreaterThanOrEqual(1 + (o.radius ?? 1));
  });

  it('stands a box on a raised floor plane, and keeps values to the centimetre', () => {
    const scene: Scene = { camera: { position: [3, 4, 6], lookAt: [1.234567, 0.5, -0.7654321] }, objects: [{ type: 'plane', point: [0, 0.5, 0], normal: [0, 1, 0] }] };
    expect(floorHeight(scene)).toBe(0.5);
    const box = last(addObject(scene, 'box'));
    expect(box).toMatchObject({ type: 'box' });
    const c = (box as { center: Vec3 }).center;
    expect(c[1]).toBe(1);
    for (const v of c) expect(Math.round(v * 100) / 100).toBe(v);
  });

  it('rests a new mesh on the floor by its lowest vertex', () => {
    const scene: Scene = { objects: [] };
    const mesh = last(addMesh(scene, TETRAHEDRON_OBJ, 2)) as { position: Vec3; scale: number };
    const { min } = meshBounds(mesh, parseObj(TETRAHEDRON_OBJ));
    expect(min[1]).toBeCloseTo(0, 9);
    const octahedron = last(addObject(scene, 'mesh')) as { position: Vec3 };
    expect(octahedron.position[1]).toBe(1); // corners 1 m from the centre
  });

  it('finds a spot even when the camera looks straight down', () => {
    const scene: Scene = { camera: { position: [0, 10, 0], lookAt: [0, 0, 0], up: [0, 0, -1] }, objects: [] };
    const p = placeOnFloor(scene, 1, 1);
    expect(p[1]).toBe(1);
    expect(inImage(scene, p)).toBe(true);
    expect(Math.hypot(p[0], p[2])).toBeGreaterThanOrEqual(1 + CLEARANCE);
  });
});
