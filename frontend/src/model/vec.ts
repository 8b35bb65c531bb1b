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
