/** The three.js geometry of a parsed OBJ mesh, as the preview draws it (pure: no renderer, no DOM). */
import { Box3, BufferAttribute, BufferGeometry, Sphere, Vector3 } from 'three';
import type { ParsedObj } from './obj';

/**
 * A three.js geometry of a parsed OBJ, in its own coordinates, indexed as the OBJ shares its
 * corners. With the OBJ's vertex normals it is smooth, as the renderer shades it; without, it has
 * no normals and is drawn with a flat-shaded material ({@link flatShaded}): each triangle its face
 * normal, worked out per pixel, as the renderer shades a mesh without normals. Nothing is computed
 * per triangle here, and a 200,000-triangle OBJ uploads a quarter of what one vertex per corner
 * would. Its bounding box and sphere are set here in one tight pass over the coordinates, where
 * three.js took two passes of vector calls (21 ms of the first frame on 200,978 triangles, in a
 * trace of the browser test's import). The caller owns it and disposes it.
 */
export function meshGeometry(parsed: ParsedObj): BufferGeometry {
  const geometry = new BufferGeometry();
  geometry.setAttribute('position', new BufferAttribute(parsed.positions, 3));
  geometry.setIndex(new BufferAttribute(parsed.indices, 1));
  if (parsed.normals) geometry.setAttribute('normal', new BufferAttribute(parsed.normals, 3));
  geometry.boundingBox = boxOf(parsed.positions);
  geometry.boundingSphere = geometry.boundingBox.getBoundingSphere(new Sphere());
  return geometry;
}

/** The box around x, y, z triples (empty for none). */
function boxOf(positions: Float32Array): Box3 {
  const box = new Box3();
  let [x0, y0, z0, x1, y1, z1] = [Infinity, Infinity, Infinity, -Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3) {
    const x = positions[i], y = positions[i + 1], z = positions[i + 2];
    if (x < x0) x0 = x;
    if (x > x1) x1 = x;
    if (y < y0) y0 = y;
    if (y > y1) y1 = y;
    if (z < z0) z0 = z;
    if (z > z1) z1 = z;
  }
  if (positions.length > 0) box.set(new Vector3(x0, y0, z0), new Vector3(x1, y1, z1));
  return box;
}

/** Whether a mesh is drawn flat (its material with `flatShading`): an OBJ without vertex normals. */
export function flatShaded(parsed: ParsedObj): boolean {
  return !parsed.normals;
}
