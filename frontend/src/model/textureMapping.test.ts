import { describe, expect, it } from 'vitest';
import { dot } from './vec';
import { rotateByQuaternion, sceneToThree, textureToThree, type MeshDescriptor } from './toThree';
import type { Scene, Vec3 } from './types';

const ID = `sha256-${'d'.repeat(64)}`;
const checker = { type: 'checker' as const, colors: ['#ffffff', '#202020'] as [string, string], size: 0.5 };

/** The texture coordinate three.js gives a plane quad's point (u, v), and that point in the world. */
function planePoint(m: MeshDescriptor, u: number, v: number): { tex: [number, number]; world: Vec3; ex: Vec3; ey: Vec3 } {
  const t = m.material.texture!;
  const size = m.scale[0];
  const ex = rotateByQuaternion([1, 0, 0], m.quaternion);
  const ey = rotateByQuaternion([0, 1, 0], m.quaternion);
  const world = [0, 1, 2].map((k) => m.position[k] + ex[k] * (u - 0.5) * size + ey[k] * (v - 0.5) * size) as Vec3;
  return { tex: [u * t.repeat[0] + t.offset[0], v * t.repeat[1] + t.offset[1]], world, ex, ey };
}

describe('textures in the preview', () => {
  it('repeats a checker once per two squares of a surface’s UV unit, and an image by its scale', () => {
    expect(textureToThree(checker)).toEqual({ kind: 'checker', colors: ['#ffffff', '#202020'], repeat: [1, 1], offset: [0, 0] });
    expect(textureToThree({ type: 'image', asset: ID, scale: [4, 2] })).toEqual({ kind: 'image', asset: ID, repeat: [4, 2], offset: [0, 0] });
    expect(textureToThree({ type: 'image', asset: ID })).toMatchObject({ repeat: [1, 1] });
    expect(textureToThree(undefined)).toBeUndefined();
  });

  it('lays a plane’s checker in metres, fixed in the world wherever the camera stands', () => {
    const scene = (camera: Vec3): Scene => ({
      camera: { position: camera, lookAt: [0, 0, 0] },
      objects: [{ type: 'plane', point: [0, 0, 0], normal: [0, 1, 0.2], material: { type: 'chalk', texture: checker } }],
    });
    for (const camera of [[0, 2, 8], [13, 5, -7]] as Vec3[]) {
      const plane = sceneToThree(scene(camera)).meshes[0];
      for (const [u, v] of [[0.5, 0.5], [0.5001, 0.4999], [0.49, 0.51]]) {
        const { tex, world, ex, ey } = planePoint(plane, u, v);
        // one texture repeat is two 0.5 m squares: the coordinate is the world position along the quad's axes / 1 m
        expect(tex[0]).toBeCloseTo(dot(world, ex) / 1, 6);
        expect(tex[1]).toBeCloseTo(dot(world, ey) / 1, 6);
      }
    }
  });

  it('gives every material kind its texture, and leaves untextured ones as they were', () => {
    const scene: Scene = { objects: [{ type: 'sphere', material: { type: 'metal', texture: checker } }, { type: 'box', material: { type: 'glass' } }] };
    const [sphere, box] = sceneToThree(scene).meshes;
    expect(sphere.material).toMatchObject({ kind: 'standard', texture: { kind: 'checker', repeat: [1, 1] } });
    expect(box.material.texture).toBeUndefined();
  });
});
