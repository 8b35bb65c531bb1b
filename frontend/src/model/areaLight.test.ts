import { Object3D, RectAreaLight, Vector3 } from 'three';
import { describe, expect, it } from 'vitest';
import { areaLightCorners, areaLightFrame, areaLightOutline } from './areaLight';
import type { Vec3 } from './types';
import { cross, dot, length, normalize, sub } from './vec';

/** The frame three.js gives a RectAreaLight at `position` that looks at `lookAt`: its x, y and -z axes. */
function threeFrame(position: Vec3, lookAt: Vec3) {
  const light = new RectAreaLight();
  light.position.set(...position);
  light.lookAt(...lookAt);
  light.updateMatrixWorld();
  const axis = (x: number, y: number, z: number) => new Vector3(x, y, z).applyQuaternion(light.quaternion).toArray() as Vec3;
  return { right: axis(1, 0, 0), up: axis(0, 1, 0), front: axis(0, 0, -1) };
}

const expectClose = (a: Vec3, b: Vec3, digits = 9) => a.forEach((v, i) => expect(v).toBeCloseTo(b[i], digits));

describe('areaLightFrame', () => {
  const cases: [string, Vec3, Vec3][] = [
    ['aimed sideways', [0, 2, 5], [0, 1, 0]],
    ['aimed obliquely', [3, 4, -2], [-1, 0.5, 2]],
    ['straight down', [1, 3, 1], [1, 0, 1]],
    ['straight up', [0, -2, 0], [0, 5, 0]],
    ['on its target', [1, 1, 1], [1, 1, 1]],
    ['far from the origin', [1e5, 3, -1e5], [1e5 + 1, 0, -1e5]],
  ];

  it.each(cases)('is the frame three.js gives a RectAreaLight %s', (_, position, lookAt) => {
    const ours = areaLightFrame(position, lookAt);
    const three = threeFrame(position, lookAt);
    expectClose(ours.right, three.right, 6);
    expectClose(ours.up, three.up, 6);
    expectClose(ours.front, three.front, 6);
  });

  it('is a right-handed orthonormal frame facing its target, its width level with the ground', () => {
    const position: Vec3 = [2, 3, 4];
    const lookAt: Vec3 = [0, 0, 0];
    const { right, up, front } = areaLightFrame(position, lookAt);
    for (const v of [right, up, front]) expect(length(v)).toBeCloseTo(1, 12);
    expect(dot(right, up)).toBeCloseTo(0, 12);
    expect(dot(up, front)).toBeCloseTo(0, 12);
    expectClose(cross(right, up), front.map((c) => -c) as Vec3, 12); // three's z points back
    expectClose(front, normalize(sub(lookAt, position)), 12);
    expect(right[1]).toBeCloseTo(0, 12);
  });

  it('looking straight down puts the width along x and the height along -z, as three.js', () => {
    const { right, up, front } = areaLightFrame([0, 3, 0], [0, 0, 0]);
    expectClose(right, [1, 0, 0], 6);
    expectClose(up, [0, 0, -1], 3);
    expectClose(front, [0, -1, 0], 3); // three tilts it by 1e-4
  });
});

describe('areaLightCorners', () => {
  it('spans the size about the position, in the plane facing lookAt', () => {
    const corners = areaLightCorners([0, 3, 0], [2, 1], [0, 0, 0]);
    const xs = corners.map((c) => c[0]);
    const ys = corners.map((c) => c[1]);
    const zs = corners.map((c) => c[2]);
    expect(Math.max(...xs) - Math.min(...xs)).toBeCloseTo(2, 6);
    expect(Math.max(...zs) - Math.min(...zs)).toBeCloseTo(1, 6);
    ys.forEach((y) => expect(y).toBeCloseTo(3, 3));
    expect(length(sub(corners[0], corners[2]))).toBeCloseTo(Math.hypot(2, 1), 12);
  });

  it('is where three.js puts the corners of a RectAreaLight of that size', () => {
    const position: Vec3 = [1, 2, 3];
    const lookAt: Vec3 = [-2, 0, 1];
    const holder = new Object3D();
    const light = new RectAreaLight(0xffffff, 1, 3, 0.5);
    light.position.set(...position);
    holder.add(light);
    light.lookAt(...lookAt);
    light.updateMatrixWorld();
    const three = [[1, -1], [-1, -1], [-1, 1], [1, 1]].map(([sx, sy]) =>
      new Vector3((sx * light.width) / 2, (sy * light.height) / 2, 0).applyMatrix4(light.matrixWorld).toArray() as Vec3);
    areaLightCorners(position, [3, 0.5], lookAt).forEach((c, i) => expectClose(c, three[i], 9));
  });
});

describe('areaLightOutline', () => {
  it('shows a light facing down as its full rectangle from above and as a line from the side', () => {
    const top = areaLightOutline('top', [1, 3, 2], [2, 1], [1, 0, 2]);
    expect(top.centre).toEqual([1, 2]);
    expect(top.aim).toEqual([1, 2]);
    const xs = top.corners.map((c) => c[0]);
    const zs = top.corners.map((c) => c[1]);
    expect(Math.max(...xs) - Math.min(...xs)).toBeCloseTo(2, 6);
    expect(Math.max(...zs) - Math.min(...zs)).toBeCloseTo(1, 6);
    expect(Math.hypot(...top.front)).toBeCloseTo(0, 3); // it faces along the top view's depth
    const side = areaLightOutline('side', [1, 3, 2], [2, 1], [1, 0, 2]);
    side.corners.forEach((c) => expect(c[1]).toBeCloseTo(3, 3)); // edge-on: a line at y = 3
    expect(side.front[0]).toBeCloseTo(0, 3);
    expect(side.front[1]).toBeCloseTo(-1, 6);
    expect(side.aim).toEqual([1, 0]);
  });

  it('shows a light facing along x from above as a line across z, facing +x', () => {
    const top = areaLightOutline('top', [0, 1, 0], [2, 1], [5, 1, 0]);
    top.corners.forEach((c) => expect(c[0]).toBeCloseTo(0, 12));
    const zs = top.corners.map((c) => c[1]);
    expect(Math.max(...zs) - Math.min(...zs)).toBeCloseTo(2, 12);
    expect(top.front[0]).toBeCloseTo(1, 12);
    expect(top.front[1]).toBeCloseTo(0, 12);
  });
});
