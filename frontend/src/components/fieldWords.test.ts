import { describe, expect, it } from 'vitest';
import type { Scene } from '../model/types';
import { describeField, plainMessage } from './fieldWords';

const SCENE: Scene = { objects: [{ type: 'box' }, { type: 'sphere', radius: -1 }] };

describe('describeField', () => {
  it('names fields as the inspector does', () => {
    expect(describeField(SCENE, 'objects[1].radius')).toBe('Sphere 2 › Radius');
    expect(describeField(SCENE, 'objects[0].center[2]')).toBe('Box 1 › Center z');
    expect(describeField(SCENE, 'objects[0].material.ior')).toBe('Box 1 › Material › Index of refraction');
    expect(describeField(SCENE, 'objects[1]')).toBe('Sphere 2');
    expect(describeField(SCENE, 'lights[0].intensity')).toBe('Light 1 › Intensity');
    expect(describeField(SCENE, 'camera.up')).toBe('Camera › Up');
    expect(describeField(SCENE, 'camera.lookAt[1]')).toBe('Camera › Look at y');
    expect(describeField(SCENE, 'image.width')).toBe('Image › Width');
    expect(describeField(SCENE, 'render.samples')).toBe('Render › Samples per pixel');
    expect(describeField(SCENE, 'background')).toBe('Scene › Background');
    const lit: Scene = { objects: [], lights: [{ type: 'point', radius: -1 }, { type: 'area', size: [0, 1] }] };
    expect(describeField(lit, 'lights[0].radius')).toBe('Light 1 › Radius');
    expect(describeField(lit, 'lights[1].size[0]')).toBe('Area light 2 › Size w');
    expect(describeField(lit, 'lights[1].lookAt[2]')).toBe('Area light 2 › Aim z');
    expect(describeField(lit, 'lights[1].twoSided')).toBe('Area light 2 › Two-sided');
  });
});

describe('plainMessage', () => {
  it('drops configuration keys and names fields in words', () => {
    const server = "800 x 600 pixels x 1024 samples = 491,520,000 samples, more than this server's render budget of 268,435,456 samples per render (studio.limits.max-pixel-samples); lower render.samples or the image size";
    const plain = plainMessage(SCENE, server);
    expect(plain).not.toContain('studio.');
    expect(plain).toContain('render budget of 268,435,456 samples per render; lower Render › Samples per pixel or the image size');
    expect(plainMessage(SCENE, 'must differ from camera.position')).toBe('must differ from Camera › Position');
    expect(plainMessage({ objects: [], lights: [{ type: 'area' }] }, 'must differ from lights[0].position')).toBe('must differ from Area light 1 › Position');
    expect(plainMessage(SCENE, 'set studio.limits.max-width higher')).toBe('set a server setting higher');
  });
});
