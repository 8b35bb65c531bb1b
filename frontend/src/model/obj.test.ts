import { Box3, Mesh, MeshBasicMaterial } from 'three';
import { readFileSync } from 'node:fs';
import { describe, expect, it } from 'vitest';
import { gridObj, TETRAHEDRON_OBJ } from '../test/meshes';
import { SCENES_DIR } from '../test/scenes';
import { meshBounds, ObjError, parseObj, scaleToFit } from './obj';
import { meshGeometry } from './meshGeometry';
import type { Vec3 } from './types';

const TRIANGLE = 'v 0 0 0\nv 1 0 0\nv 0 1 0\n';

/** The error message of parsing `text`. */
function problem(text: string): string {
  try {
    parseObj(text);
  } catch (error) {
    expect(error).toBeInstanceOf(ObjError);
    return (error as Error).message;
  }
  throw new Error('expected an ObjError');
}

describe('parseObj', () => {
  it('reads vertices and faces of every corner form, dropping texture indices', () => {
    for (const face of ['f 1 2 3', 'f 1/1 2/2 3/3', 'f 1/1/1 2/2/1 3/3/1', 'f 1//1 2//1 3//1']) {
      const parsed = parseObj(`${TRIANGLE}vt 0 0\nvt 1 0\nvt 0 1\nvn 0 0 1\n${face}\n`);
      expect(parsed.triangleCount, face).toBe(1);
      expect([...parsed.positions], face).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
      expect([...parsed.indices], face).toEqual([0, 1, 2]);
      // Normals only when every corner names one.
      expect(parsed.normals && [...parsed.normals], face).toEqual(face.includes('//') || face.includes('/1/1') ? [0, 0, 1, 0, 0, 1, 0, 0, 1] : undefined);
    }
  });

  it('resolves negative indices against the vertices so far', () => {
    const parsed = parseObj('v 9 9 9\nv 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 1\nf -3//-1 -2//-1 -1//-1\nv 5 5 5\nf -4 -3 -1\n');
    expect([...parsed.indices]).toEqual([1, 2, 3, 1, 2, 4]);
    expect(parsed.normals).toBeUndefined(); // the second face has none
  });

  it('fans polygons into triangles around their first corner', () => {
    const quad = parseObj('v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nf 1 2 3 4\n');
    expect(quad.triangleCount).toBe(2);
    expect([...quad.indices]).toEqual([0, 1, 2, 0, 2, 3]);
    const pentagon = parseObj('v 0 0 0\nv 1 0 0\nv 2 1 0\nv 1 2 0\nv 0 1 0\nf 1 2 3 4 5\n');
    expect([...pentagon.indices]).toEqual([0, 1, 2, 0, 2, 3, 0, 3, 4]);
    expect(parseObj(gridObj(3)).triangleCount).toBe(18);
  });

  it('ignores comments, blank lines, groups, smoothing, materials and Windows line ends', () => {
    const text = ['# a comment', 'mtllib x.mtl', 'o thing', 'g part', 's 1', 'usemtl red', '', 'v 0 0 0 1 # w ignored', 'v 1 0 0', 'v 0 1 0', 'vt 0.5 0.5', 'f 1 2 3 # done'].join('\r\n');
    const parsed = parseObj(text);
    expect(parsed.triangleCount).toBe(1);
    expect([...parsed.positions]).toEqual([0, 0, 0, 1, 0, 0, 0, 1, 0]);
  });

  it('splits a position used with several normals into several vertices, and shares the others', () => {
    const parsed = parseObj('v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nvn 0 0 1\nvn 0 1 0\nf 1//1 2//1 3//1\nf 2//1 4//2 3//1\nf 1//2 2//1 4//2\n');
    // (position, normal) pairs in order of first use: (1,1) (2,1) (3,1) (4,2) (1,2).
    expect(parsed.positions.length / 3).toBe(5);
    expect([...parsed.indices]).toEqual([0, 1, 2, 1, 3, 2, 4, 1, 3]);
    expect([...parsed.positions.slice(12, 15)]).toEqual([0, 0, 0]);
    expect([...parsed.normals!.slice(12, 15)]).toEqual([0, 1, 0]);
    expect([...parsed.normals!.slice(0, 3)]).toEqual([0, 0, 1]);
  });

  it('names the line of each problem', () => {
    const lines = (last: string) => `v 0 0 0\nv 1 0 0\nv 0 1 0\n# four\n\n\n${last}\n`;
    expect(problem(lines('f 1 2 12'))).toBe('line 7: index 12 out of range (3 vertices so far)');
    expect(problem(lines('f 1 2 -4'))).toMatch(/^line 7: index -4 out of range/);
    expect(problem(lines('f 0 1 2'))).toBe('line 7: vertex index 0 is not valid (OBJ indices start at 1)');
    expect(problem(lines('f 1 2'))).toBe('line 7: face has 2 vertices, needs at least 3');
    expect(problem(lines('f 1 2 x'))).toBe("line 7: 'x' is not a valid index");
    expect(problem(lines('f 1//1 2//1 3//1'))).toBe('line 7: normal index 1 out of range (0 normals so far)');
    expect(problem('v 1 2\n')).toBe('line 1: vertex needs 3 coordinates');
    expect(problem('v 1 2 abc\n')).toBe("line 1: 'abc' is not a number");
    expect(problem('v 1 2 0x10\n')).toBe("line 1: '0x10' is not a number");
    expect(problem('\nv 1 2 1e999\n')).toBe("line 2: vertex coordinate '1e999' is not finite");
    expect(problem('vn 0 0 0\n')).toBe('line 1: normal has zero length');
  });

  it('reads an empty text as a mesh without triangles', () => {
    expect(parseObj('')).toMatchObject({ triangleCount: 0 });
    expect(parseObj('# nothing\n').positions).toHaveLength(0);
  });

  it('reads the torus knot shipped with the example scenes, with its vertex normals', () => {
    const parsed = parseObj(readFileSync(SCENES_DIR + 'meshes/torus-knot.obj', 'utf8'));
    expect(parsed.triangleCount).toBe(3000);
    expect(parsed.positions.length / 3).toBe(1500);
    expect(parsed.normals).toHaveLength(parsed.positions.length);
  });

  it('reads 100 000 triangles quickly', () => {
    const text = gridObj(224); // 100 352 triangles
    const start = performance.now();
    const parsed = parseObj(text);
    expect(parsed.triangleCount).toBe(2 * 224 * 224);
    expect(performance.now() - start).toBeLessThan(5000);
  });
});

describe('meshBounds', () => {
  const tetra = parseObj(TETRAHEDRON_OBJ);

  it('is the OBJ’s own box when the mesh is not moved', () => {
    expect(meshBounds({}, tetra)).toEqual({ min: [0, 0, 0], max: [1, 1, 1] });
  });

  it('scales, rotates (about z, then x) and moves a tetrahedron as worked out by hand', () => {
    // Scale 2 then 90° about z: (x, y, z) -> (-y, x, z); the corners (2,0,0), (0,2,0), (0,0,2) go to
    // (0,2,0), (-2,0,0), (0,0,2); then moved by (10, 20, 30).
    const b = meshBounds({ position: [10, 20, 30], scale: 2, rotation: [0, 0, 90] }, tetra);
    expectVec(b.min, [8, 20, 30]);
    expectVec(b.max, [10, 22, 32]);
    // 90° about x: (x, y, z) -> (x, -z, y); (0,0,2) -> (0,-2,0) and (0,2,0) -> (0,0,2).
    const c = meshBounds({ scale: 2, rotation: [90, 0, 0] }, tetra);
    expectVec(c.min, [0, -2, 0]);
    expectVec(c.max, [2, 0, 2]);
    // 45° about y: (1,0,0) -> (√½, 0, -√½) and (0,0,1) -> (√½, 0, √½).
    const d = meshBounds({ position: [0, 1, 0], scale: 1, rotation: [0, 45, 0] }, tetra);
    expectVec(d.min, [0, 1, -Math.SQRT1_2]);
    expectVec(d.max, [Math.SQRT1_2, 2, Math.SQRT1_2]);
  });

  it('agrees with a three.js Object3D placed the same way (Euler XYZ, uniform scale)', () => {
    const grid = parseObj(gridObj(4, 3));
    const geometry = meshGeometry(grid);
    for (const [position, scale, rotation] of [
      [[1, 2, 3], 0.5, [30, 60, 90]],
      [[-4, 0, 2], 3, [-120, 15, 200]],
      [[0, 0, 0], 1.25, [10, -80, 45]],
    ] as [Vec3, number, Vec3][]) {
      const mesh = new Mesh(geometry, new MeshBasicMaterial());
      mesh.position.set(...position);
      mesh.rotation.set(...(rotation.map((d) => (d * Math.PI) / 180) as Vec3), 'XYZ');
      mesh.scale.setScalar(scale);
      mesh.updateMatrixWorld();
      const box = new Box3().setFromObject(mesh, true);
      const b = meshBounds({ position, scale, rotation }, grid);
      expectVec(b.min, box.min.toArray(), 5);
      expectVec(b.max, box.max.toArray(), 5);
    }
  });

  it('follows a move without working the rotation out again, and a new rotation with it', () => {
    const a = meshBounds({ position: [0, 0, 0], rotation: [0, 0, 90] }, tetra);
    const b = meshBounds({ position: [1, 1, 1], rotation: [0, 0, 90] }, tetra);
    expectVec(b.min, a.min.map((x) => x + 1) as Vec3);
    expectVec(meshBounds({ rotation: [0, 0, 0] }, tetra).max, [1, 1, 1]);
  });

  it('gives the scale that makes the largest side about 2 m', () => {
    expect(scaleToFit(tetra)).toBe(2);
    expect(scaleToFit(parseObj(gridObj(2, 0.0347)))).toBe(57.6);
    expect(scaleToFit(parseObj('v 1 1 1\n'))).toBe(1);
  });
});

function expectVec(actual: readonly number[], expected: readonly number[], digits = 9) {
  expect(actual).toHaveLength(3);
  actual.forEach((x, i) => expect(x, `component ${i}`).toBeCloseTo(expected[i], digits));
}
