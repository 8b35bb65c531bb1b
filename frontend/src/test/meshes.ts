/** OBJ texts for tests. */

/** The unit tetrahedron: the origin and the three unit points, outward-facing triangles. */
export const TETRAHEDRON_OBJ = ['v 0 0 0', 'v 1 0 0', 'v 0 1 0', 'v 0 0 1', 'f 1 3 2', 'f 1 2 4', 'f 1 4 3', 'f 2 3 4', ''].join('\n');

/**
 * A flat grid of `n` x `m` quads (2 n m triangles) in the x-z plane, `size` metres along x,
 * written as quads, so it also exercises fan triangulation.
 */
export function gridObj(n: number, size = 1, m = n): string {
  const lines: string[] = ['# grid', 'o grid'];
  for (let i = 0; i <= n; i++) for (let j = 0; j <= m; j++) lines.push(`v ${(size * i) / n} 0 ${(size * j) / n}`);
  const at = (i: number, j: number) => i * (m + 1) + j + 1;
  for (let i = 0; i < n; i++) for (let j = 0; j < m; j++) lines.push(`f ${at(i, j)} ${at(i, j + 1)} ${at(i + 1, j + 1)} ${at(i + 1, j)}`);
  return lines.join('\n') + '\n';
}
