/** Small pure vector helpers on {@link Vec3} tuples. */
import type { Vec3 } from './types';

export const add = (a: Vec3, b: Vec3): Vec3 => [a[0] + b[0], a[1] + b[1], a[2] + b[2]];
export const sub = (a: Vec3, b: Vec3): Vec3 => [a[0] - b[0], a[1] - b[1], a[2] - b[2]];
export const scale = (a: Vec3, s: number): Vec3 => [a[0] * s, a[1] * s, a[2] * s];
export const dot = (a: Vec3, b: Vec3): number => a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
export const cross = (a: Vec3, b: Vec3): Vec3 => [
  a[1] * b[2] - a[2] * b[1],
  a[2] * b[0] - a[0] * b[2],
  a[0] * b[1] - a[1] * b[0],
];
export const length = (a: Vec3): number => Math.hypot(a[0], a[1], a[2]);
export const normalize = (a: Vec3): Vec3 => {
  const l = length(a);
  return l === 0 ? [0, 0, 0] : scale(a, 1 / l);
};
export const vecEquals = (a: Vec3, b: Vec3): boolean => a[0] === b[0] && a[1] === b[1] && a[2] === b[2];

/**
 * Rotation of a vector by Euler angles in degrees, three.js order 'XYZ' (the matrix is
 * Rx · Ry · Rz, so z is applied first to the vector), as the engine rotates boxes.
 */
export function rotateXYZ(v: Vec3, degrees: Vec3): Vec3 {
  const [ax, ay, az] = degrees.map((d) => (d * Math.PI) / 180);
  // Rz
  let x = v[0] * Math.cos(az) - v[1] * Math.sin(az);
  let y = v[0] * Math.sin(az) + v[1] * Math.cos(az);
  let z = v[2];
  // Ry
  const x2 = x * Math.cos(ay) + z * Math.sin(ay);
  z = -x * Math.sin(ay) + z * Math.cos(ay);
  x = x2;
  // Rx
  const y2 = y * Math.cos(ax) - z * Math.sin(ax);
  z = y * Math.sin(ax) + z * Math.cos(ax);
  y = y2;
  return [x, y, z];
}

/** A 3x3 matrix, row-major: `m[3 * row + column]`. */
export type Mat3 = [number, number, number, number, number, number, number, number, number];

/**
 * The matrix of {@link rotateXYZ}: Rx · Ry · Rz for Euler angles in degrees (three.js
 * `Matrix4.makeRotationFromEuler`, order 'XYZ'). Worked out once for many points (meshes).
 */
export function rotationMatrixXYZ(degrees: Vec3): Mat3 {
  const [ax, ay, az] = degrees.map((d) => (d * Math.PI) / 180);
  const [a, b] = [Math.cos(ax), Math.sin(ax)];
  const [c, d] = [Math.cos(ay), Math.sin(ay)];
  const [e, f] = [Math.cos(az), Math.sin(az)];
  return [
    c * e, -c * f, d,
    a * f + b * e * d, a * e - b * f * d, -b * c,
    b * f - a * e * d, b * e + a * f * d, a * c,
  ];
}

/** `m · v`. */
export function applyMat3(m: Mat3, v: Vec3): Vec3 {
  return [
    m[0] * v[0] + m[1] * v[1] + m[2] * v[2],
    m[3] * v[0] + m[4] * v[1] + m[5] * v[2],
    m[6] * v[0] + m[7] * v[1] + m[8] * v[2],
  ];
}
