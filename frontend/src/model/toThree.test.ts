import { BoxGeometry, BufferAttribute, BufferGeometry, Euler, Mesh, Quaternion, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import * as edits from './edits';
import { carryIds, idOf } from './identity';
import { cameraFrame } from './projection';
import { flatShaded, meshGeometry } from './meshGeometry';
import { areaLuminance, letterbox, LIGHT_SCALE, makeRenderCamera, planeSize, projectToPixel, quaternionFromZ, sceneToThree } from './toThree';
import { MeshCache, type MeshLookup } from './meshCache';
import { parseObj } from './obj';
import { gridObj, TETRAHEDRON_OBJ } from '../test/meshes';
import type { Scene, Vec3 } from './types';
import { rotateXYZ } from './vec';

/** The engine's camera (Camera.java + Renderer.java), ported: the ray through a pixel position. */
function engineRay(position: Vec3, lookAt: Vec3, up: Vec3, fov: number, width: number, height: number) {
  const f = cameraFrame(position, lookAt, up)!;
  const t = Math.tan((fov * Math.PI) / 180 / 2);
  const aspect = width / height;
  /** `px`, `py` are continuous: pixel (x, y)'s centre is (x + 0.5, y + 0.5). */
  return (px: number, py: number): Vec3 => {
    const ndcX = (2 * px) / width - 1;
    const ndcY = 1 - (2 * py) / height;
    const x = ndcX * t * aspect;
    const y = ndcY * t;
    return [0, 1, 2].map((i) => x * f.u[i] + y * f.v[i] - f.w[i]) as Vec3;
  };
}

/** Inverts the engine's mapping: the pixel position whose ray passes through `p`. */
function enginePixel(position: Vec3, lookAt: Vec3, up: Vec3, fov: number, width: number, height: number, p: Vec3) {
  const f = cameraFrame(position, lookAt, up)!;
  const d = [0, 1, 2].map((i) => p[i] - position[i]) as Vec3;
  const depth = -(d[0] * f.w[0] + d[1] * f.w[1] + d[2] * f.w[2]);
  const x = (d[0] * f.u[0] + d[1] * f.u[1] + d[2] * f.u[2]) / depth;
  const y = (d[0] * f.v[0] + d[1] * f.v[1] + d[2] * f.v[2]) / depth;
  const t = Math.tan((fov * Math.PI) / 180 / 2);
  const ndcX = x / (t * (width / height));
  const ndcY = y / t;
  return [((ndcX + 1) * width) / 2, ((1 - ndcY) * height) / 2] as [number, number];
}

function rng(seed: number) {
  let s = seed >>> 0;
  return () => {
    s = (s * 1664525 + 1013904223) >>> 0;
    return s / 2 ** 32;
  };
}

const CAMERAS: { position: Vec3; lookAt: Vec3; up: Vec3 }[] = [
  { position: [0, 2, 8], lookAt: [0, 0, 0], up: [0, 1, 0] },
  { position: [4, 3, 6], lookAt: [0, 0.7, 0], up: [0, 1, 0] },
  { position: [-7, 1, -3], lookAt: [2, 2, 5], up: [0.2, 1, 0.1] },
  { position: [1e3, 50, -200], lookAt: [990, 52, -190], up: [0, 0, 1] },
];

describe('the preview camera frames the scene as the engine does', () => {
  const sizes: [number, number][] = [[800, 600], [600, 800], [1920, 1080], [1, 1]];
  for (const [width, height] of sizes) {
    for (const fov of [10, 50, 120]) {
      it(`puts world points on the engine's pixel within half a pixel at ${width}x${height}, fov ${fov}`, () => {
        const r = rng(width * 7 + height * 13 + fov);
        for (const cam of CAMERAS) {
          const scene: Scene = { image: { width, height }, camera: { ...cam, fov }, objects: [] };
          const three = makeRenderCamera(sceneToThree(scene).camera);
          const ray = engineRay(cam.position, cam.lookAt, cam.up, fov, width, height);
          let checked = 0;
          for (let i = 0; i < 60; i++) {
            // A pixel position inside the image, and a point some way along its engine ray.
            const px = r() * width;
            const py = r() * height;
            const dir = ray(px, py);
            const dist = 0.5 + r() * 20;
            const p = [0, 1, 2].map((k) => cam.position[k] + dir[k] * dist) as Vec3;
            const [ex, ey] = enginePixel(cam.position, cam.lookAt, cam.up, fov, width, height, p);
            expect(Math.abs(ex - px)).toBeLessThan(1e-6 * Math.max(1, width));
            expect(Math.abs(ey - py)).toBeLessThan(1e-6 * Math.max(1, height));
            const [tx, ty] = projectToPixel(three, p, width, height);
            expect(Math.abs(tx - ex)).toBeLessThan(0.5);
            expect(Math.abs(ty - ey)).toBeLessThan(0.5);
            checked++;
          }
          expect(checked).toBe(60);
        }
      });
    }
  }

  it('sees the target at the image centre', () => {
    const three = makeRenderCamera(sceneToThree({ camera: { lookAt: [1, 1, 1] }, objects: [] }).camera);
    const [x, y] = projectToPixel(three, [1, 1, 1], 800, 600);
    expect(x).toBeCloseTo(400, 6);
    expect(y).toBeCloseTo(300, 6);
  });
});

describe('sceneToThree', () => {
  const scene: Scene = {
    background: '#112233',
    ambient: 0.1,
    lights: [{ type: 'point', position: [1, 2, 3], color: '#ff0000', intensity: 0.5, falloff: true }, { type: 'point' }],
    objects: [
      { type: 'sphere', center: [1, 2, 3], radius: 2, material: { type: 'flat', color: '#00ff00' } },
      { type: 'box', center: [0, 1, 0], size: [1, 2, 3], rotation: [10, 20, 30], material: { type: 'plastic' } },
      { type: 'plane', point: [0, -1, 0], normal: [0, 2, 0], material: { type: 'glass', ior: 1.4 } },
      { type: 'sphere', material: { type: 'metal', reflectivity: 1 } },
      { type: 'sphere', material: { type: 'mirror' } },
      { type: 'sphere' },
    ],
  };

  it('marks every object and light of a multi-selection', () => {
    const d = sceneToThree(scene, { kind: 'object', index: 1 }, undefined, [{ kind: 'object', index: 3 }, { kind: 'light', index: 1 }, { kind: 'object', index: 1 }]);
    expect(d.meshes.map((m) => m.selected)).toEqual([false, true, false, true, false, false]);
    expect(d.lights.map((l) => l.selected)).toEqual([false, true]);
  });

  it('maps geometry, materials, lights, background and ambient', () => {
    const d = sceneToThree(scene, { kind: 'object', index: 1 });
    expect(d.background).toBe('#112233');
    expect(d.ambient).toBeCloseTo(0.1 * LIGHT_SCALE);
    expect(d.meshes.map((m) => m.geometry)).toEqual(['sphere', 'box', 'plane', 'sphere', 'sphere', 'sphere']);
    expect(d.meshes[0]).toMatchObject({ position: [1, 2, 3], scale: [2, 2, 2], material: { kind: 'basic', color: '#00ff00' }, selected: false });
    expect(d.meshes[1]).toMatchObject({ scale: [1, 2, 3], selected: true, material: { kind: 'phong', diffuse: 0.8, specular: 0.5, shininess: 60 } });
    expect(d.meshes[1].rotation.map((a) => (a * 180) / Math.PI)).toEqual([10, 20, 30].map((a) => expect.closeTo(a, 9)));
    expect(d.meshes[2].material).toMatchObject({ kind: 'physical', ior: 1.4 });
    expect(d.meshes[2].position[1]).toBeCloseTo(-1);
    expect(d.meshes[3].material).toMatchObject({ kind: 'standard', metalness: 1 });
    expect(d.meshes[4].material).toEqual({ kind: 'standard', color: '#ffffff', metalness: 1, roughness: 0, reflects: true });
    expect(d.meshes[5].material).toMatchObject({ kind: 'lambert', diffuse: 0.9 });
    expect(d.lights).toEqual([
      { kind: 'point', id: 'light@0', index: 0, position: [1, 2, 3], color: '#ff0000', intensity: 0.5 * LIGHT_SCALE, decay: 2, selected: false, radius: 0 },
      { kind: 'point', id: 'light@1', index: 1, position: [5, 8, 5], color: '#ffffff', intensity: LIGHT_SCALE, decay: 0, selected: false, radius: 0 },
    ]);
    expect(d.camera).toMatchObject({ fov: 50, aspect: 800 / 600, position: [0, 2, 8] });
    expect(d.camera.far).toBeGreaterThan(d.extent);
  });

  it('maps a sphere light with its radius and an area light as a RectAreaLight aimed at its lookAt', () => {
    const d = sceneToThree({
      objects: [],
      lights: [
        { type: 'point', radius: 0.25 },
        { type: 'area', position: [0, 3, 0], size: [2, 0.5], lookAt: [0, 1, 0], color: '#ffeedd', intensity: 2, falloff: true, twoSided: true },
        { type: 'area', position: [0, 3, 0], size: [2, 0.5], lookAt: [0, 1, 0], intensity: 2 },
      ],
    }, { kind: 'lightAim', index: 1 });
    expect(d.lights[0]).toMatchObject({ kind: 'point', radius: 0.25, selected: false });
    expect(d.lights[1]).toEqual({
      kind: 'area', id: 'light@1', index: 1, position: [0, 3, 0], color: '#ffeedd', intensity: 2 * LIGHT_SCALE, decay: 2, selected: true,
      width: 2, height: 0.5, lookAt: [0, 1, 0], luminance: (2 * LIGHT_SCALE) / 1, twoSided: true,
    });
    // without fall-off it is matched at its aim, 2 m away
    expect(d.lights[2]).toMatchObject({ decay: 0, luminance: ((2 * LIGHT_SCALE) / 1) * 4, twoSided: false });
  });

  it('leaves out an area light it cannot draw (no size, or its aim on it); the inspector says why', () => {
    const d = sceneToThree({
      objects: [],
      lights: [{ type: 'area', size: [0, 1] }, { type: 'area', position: [1, 1, 1], lookAt: [1, 1, 1] }, { type: 'point', radius: -1 }],
    });
    expect(d.lights).toEqual([expect.objectContaining({ kind: 'point', index: 2, radius: 0 })]);
  });

  it('gives an area light the luminance whose light on its axis is a point light’s of its intensity', () => {
    // E = L·A/d² for a small rectangle; a point light of three intensity I gives I/d² with fall-off
    const luminance = areaLuminance(1.5, 0.01, 0.02, true, 3);
    expect(luminance * 0.01 * 0.02).toBeCloseTo(1.5 * LIGHT_SCALE, 12);
    expect(areaLuminance(1.5, 0.01, 0.02, false, 3) * 0.01 * 0.02 / 9).toBeCloseTo(1.5 * LIGHT_SCALE, 12);
  });

  it('carries each object’s and light’s editor id, so the preview keeps its mesh through moves and deletions', () => {
    const s = carryIds(null, scene);
    const d = sceneToThree(s);
    expect(d.meshes.map((m) => m.id)).toEqual(s.objects.map(idOf));
    expect(d.lights.map((l) => [l.id, l.index])).toEqual([['light-1', 0], ['light-2', 1]]);
    const moved = carryIds(s, edits.moveObject(s, 3, [4, 0, 0]));
    expect(sceneToThree(moved).meshes.map((m) => m.id)).toEqual(d.meshes.map((m) => m.id));
    const fewer = carryIds(moved, edits.removeLight(edits.removeObject(moved, 0), 0));
    expect(sceneToThree(fewer).meshes.map((m) => [m.id, m.index])).toEqual([['object-2', 0], ['object-3', 1], ['object-4', 2], ['object-5', 3], ['object-6', 4]]);
    expect(sceneToThree(fewer).lights.map((l) => [l.id, l.index])).toEqual([['light-2', 0]]);
  });

  it('names what has no editor id by kind and index, apart from every editor id (the default light, a scene outside the store)', () => {
    const d = sceneToThree({ objects: [{ type: 'sphere' }, { type: 'box' }] });
    expect(d.meshes.map((m) => m.id)).toEqual(['object@0', 'object@1']);
    expect(d.lights.map((l) => l.id)).toEqual(['light@0']);
  });

  it('rotates a box as the engine does (Euler XYZ in degrees)', () => {
    const d = sceneToThree(scene).meshes[1];
    const mesh = new Mesh(new BoxGeometry(1, 1, 1));
    mesh.rotation.copy(new Euler(...d.rotation, 'XYZ'));
    const v = new Vector3(0.3, -0.7, 1.1).applyEuler(mesh.rotation);
    const ours = rotateXYZ([0.3, -0.7, 1.1], [10, 20, 30]);
    expect([v.x, v.y, v.z].map((c, i) => c - ours[i]).every((e) => Math.abs(e) < 1e-12)).toBe(true);
  });

  it('turns the plane quad (+z) onto the plane normal', () => {
    for (const n of [[0, 1, 0], [0, 0, -1], [1, 1, 1], [0, -3, 0]] as Vec3[]) {
      const q = new Quaternion(...quaternionFromZ(n));
      const z = new Vector3(0, 0, 1).applyQuaternion(q);
      const len = Math.hypot(...n);
      expect(z.x).toBeCloseTo(n[0] / len, 9);
      expect(z.y).toBeCloseTo(n[1] / len, 9);
      expect(z.z).toBeCloseTo(n[2] / len, 9);
    }
  });

  it('letterboxes to the image aspect', () => {
    expect(letterbox(800, 800, 2)).toEqual({ width: 800, height: 400, left: 0, top: 200 });
    expect(letterbox(800, 300, 2)).toEqual({ width: 600, height: 300, left: 100, top: 0 });
  });
});

describe('meshes in the preview', () => {
  const cache = new MeshCache();
  const lookup: MeshLookup = (mesh) => cache.get(mesh);
  const scene: Scene = {
    objects: [
      { type: 'sphere', material: { type: 'plastic', color: '#123456', shininess: 30 } },
      { type: 'mesh', obj: TETRAHEDRON_OBJ, position: [1, 2, 3], scale: 2, rotation: [10, 20, 30], material: { type: 'plastic', color: '#123456', shininess: 30 } },
      { type: 'mesh', file: 'meshes/not-yet.obj' },
      { type: 'box' },
    ],
  };

  it('maps a mesh onto its parsed triangles, placed and coloured as the other objects', () => {
    const d = sceneToThree(scene, { kind: 'object', index: 1 }, lookup);
    // The file mesh is still loading: left out; the others keep their scene index.
    expect(d.meshes.map((m) => [m.index, m.geometry])).toEqual([[0, 'sphere'], [1, 'mesh'], [3, 'box']]);
    const m = d.meshes[1];
    expect(m.mesh).toBe((cache.get(scene.objects[1] as never) as { mesh: unknown }).mesh);
    expect(m).toMatchObject({ position: [1, 2, 3], scale: [2, 2, 2], selected: true });
    expect(m.rotation.map((a) => (a * 180) / Math.PI)).toEqual([10, 20, 30].map((a) => expect.closeTo(a, 9)));
    expect(m.material).toEqual(d.meshes[0].material);
    expect(sceneToThree(scene).meshes.map((x) => x.geometry)).toEqual(['sphere', 'box']); // no lookup: no meshes
  });

  it('puts every vertex where the scene format says: position + R(rotation) · (scale · v)', () => {
    const d = sceneToThree(scene, null, lookup).meshes[1];
    const object = new Mesh(meshGeometry(d.mesh!));
    object.position.set(...d.position);
    object.rotation.set(...d.rotation, 'XYZ');
    object.scale.set(...d.scale);
    object.updateMatrixWorld();
    const position = object.geometry.getAttribute('position');
    for (let i = 0; i < position.count; i++) {
      const world = new Vector3().fromBufferAttribute(position, i).applyMatrix4(object.matrixWorld);
      const local: Vec3 = [position.getX(i), position.getY(i), position.getZ(i)];
      const expected = rotateXYZ([2 * local[0], 2 * local[1], 2 * local[2]], [10, 20, 30]).map((c, k) => c + [1, 2, 3][k]);
      expect(world.toArray().map((c, k) => Math.abs(c - expected[k])).every((e) => e < 1e-6)).toBe(true);
    }
  });

  it('makes the scene extent reach a far-away mesh', () => {
    const far: Scene = { lights: [], objects: [{ type: 'mesh', obj: TETRAHEDRON_OBJ, position: [0, 0, -500], scale: 10 }] };
    expect(sceneToThree(far, null, lookup).extent).toBeGreaterThan(2 * 500);
  });

  it('draws a mesh without OBJ normals as indexed, without normals, flat-shaded: nothing computed per triangle', () => {
    const parsed = parseObj(TETRAHEDRON_OBJ);
    const g = meshGeometry(parsed);
    expect(Array.from(g.index!.array)).toEqual(Array.from(parsed.indices));
    expect(g.getAttribute('position').array).toBe(parsed.positions);
    expect(g.getAttribute('normal')).toBeUndefined();
    expect(flatShaded(parsed)).toBe(true);
  });

  it('gives a mesh the bounding box three.js would compute, and a sphere holding every vertex, without walking them again', () => {
    const parsed = parseObj(gridObj(7, 3));
    const g = meshGeometry(parsed);
    const computed = new BufferGeometry().setAttribute('position', new BufferAttribute(parsed.positions, 3));
    computed.computeBoundingBox();
    expect(g.boundingBox!.equals(computed.boundingBox!)).toBe(true);
    const position = g.getAttribute('position');
    const { center, radius } = g.boundingSphere!;
    for (let i = 0; i < position.count; i++) expect(new Vector3().fromBufferAttribute(position, i).distanceTo(center)).toBeLessThanOrEqual(radius * (1 + 1e-12));
    expect(meshGeometry(parsed).boundingBox).not.toBe(g.boundingBox); // each geometry its own, as three.js disposes them
  });

  it('shades smoothly with the OBJ’s normals, kept as they are', () => {
    const parsed = parseObj('v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nvn 0.6 0 0.8\nvn 0 0.6 0.8\nf 1//1 2//2 3//3\n');
    const g = meshGeometry(parsed);
    expect(Array.from(g.index!.array)).toEqual([0, 1, 2]);
    expect(Array.from(g.getAttribute('normal').array)).toEqual(Array.from(parsed.normals!));
    expect(flatShaded(parsed)).toBe(false);
  });

  describe('never shows what the render will not, and survives extreme values', () => {
    it('gives mirrors, metals and glass the scene to reflect; glass is refractive, not half-transparent', () => {
      const d = sceneToThree({
        objects: [
          {}, {},
          { type: 'plane', material: { type: 'glass', ior: 1.4 } },
          { type: 'sphere', material: { type: 'metal' } },
          { type: 'sphere', material: { type: 'mirror' } },
          { type: 'sphere', material: { type: 'chalk' } },
        ].map((o) => ({ type: 'sphere', ...o })) as Scene['objects'],
      });
      expect(d.meshes[2].material).toEqual({ kind: 'physical', color: '#ffffff', transmission: 1, ior: 1.4, roughness: 0, reflects: true });
      expect(d.meshes[3].material).toMatchObject({ reflects: true });
      expect(d.meshes[4].material).toMatchObject({ reflects: true });
      expect(d.meshes[5].material).not.toHaveProperty('reflects');
    });

    it('keeps the floor and a finite depth range with a sphere at x = 1e300', () => {
      const extreme: Scene = {
        objects: [
          { type: 'plane', point: [0, 0, 0], normal: [0, 1, 0] },
          { type: 'sphere', center: [0, 1, 0] },
          { type: 'sphere', center: [1e300, 1, 0] },
        ],
      };
      const d = sceneToThree(extreme);
      expect(d.meshes.map((m) => m.geometry)).toEqual(['plane', 'sphere']);
      expect(Math.fround(d.camera.far)).toBeLessThan(Infinity);
      for (const m of d.meshes) for (const v of [...m.position, ...m.scale]) expect(Math.abs(Math.fround(v))).toBeLessThan(1e30);
      expect(d.extent).toBe(sceneToThree({ objects: extreme.objects.slice(0, 2) }).extent);
    });

    it('draws the floor past everything a 179.9 degree camera sees', () => {
      const wide: Scene = { camera: { fov: 179.9 }, objects: [{ type: 'plane', point: [0, 0, 0], normal: [0, 1, 0] }] };
      const d = sceneToThree(wide);
      const half = d.meshes[0].scale[0] / 2;
      // at the far plane's depth the view reaches far * tan(fov / 2) * aspect to the side
      const side = d.camera.far * Math.tan((179.9 / 2) * (Math.PI / 180)) * d.camera.aspect;
      expect(half).toBeGreaterThan(side);
      expect(Number.isFinite(Math.fround(half))).toBe(true);
      expect(planeSize(100, 50, 1)).toBeGreaterThan(200);
      // the floor 2 m below the camera, 89.9 degrees off the axis, is nearer in depth than a 45-degree lens's near plane
      expect(d.camera.near).toBeLessThan(2 * Math.cos((89.9 * Math.PI) / 180) / 2);
      expect(sceneToThree({ objects: [] }).camera.near).toBeCloseTo(Math.hypot(0, 2, 8) / 1000, 12);
    });
  });
});
