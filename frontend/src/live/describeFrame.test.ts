import { describe, expect, it } from 'vitest';
import { describeFrame } from './describeFrame';
import { frameHeader } from '../test/liveFakes';

describe('describeFrame', () => {
  it('gives a refining frame its pass, samples, size and time', () => {
    expect(describeFrame(frameHeader({ pass: 4, samplesPerPixel: 1, width: 640, height: 480, millis: 38 }))).toBe('pass 4 · 1 spp · 640x480 · 38 ms');
  });

  it('calls the last frame final', () => {
    expect(describeFrame(frameHeader({ pass: 5, final: true, samplesPerPixel: 16, width: 640, height: 480, millis: 1234 }))).toBe('final · 16 spp · 640x480 · 1.2 s');
  });
});
