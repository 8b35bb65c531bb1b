import { Euler, Matrix4 } from 'three';
import { describe, expect, it } from 'vitest';
import type { Vec3 } from './types';
import { applyMat3, rotateXYZ, rotationMatrixXYZ } from './vec';

describe('rotationMatrixXYZ', () => {
  it('rotates as rotateXYZ and as three.js Matrix4.makeRotationFromEuler (order XYZ)', () => {
    for (const degrees of [[0, 0, 0], [90, 0, 0], [0, 90, 0], [0, 0, 90], [30, -45, 120], [200, 10, -75]] as Vec3[]) {
      const m = rotationMatrixXYZ(degrees);
      const three = new Matrix4().makeRotationFromEuler(new Euler(...(degrees.map((d) => (d * Math.PI) / 180) as Vec3), 'XYZ')).elements;
      for (let row = 0; row < 3; row++) for (let col = 0; col < 3; col++) {
        expect(m[3 * row + col]).toBeCloseTo(three[4 * col + row], 12); // three.js is column-major
      }
      for (const v of [[1, 0, 0], [0, 1, 0], [0, 0, 1], [0.3, -2, 5]] as Vec3[]) {
        applyMat3(m, v).forEach((x, i) => expect(x).toBeCloseTo(rotateXYZ(v, degrees)[i], 12));
      }
    }
  });
});
