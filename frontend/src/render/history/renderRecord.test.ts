import { describe, expect, it } from 'vitest';
import {
  formatFinished,
  formatSamples,
  readRecord,
  recordName,
  recordOf,
  sceneOfSent,
  type FinishedRender,
} from './renderRecord';

const SCENE = { name: 'still-life', render: { samples: 32, adaptive: 0 }, objects: [{ type: 'sphere', radius: 2 }] };

function finished(overrides: Partial<FinishedRender> = {}): FinishedRender {
  return {
    jobId: 'k3j',
    finishedAt: new Date(2025, 4, 1, 14, 3, 12).getTime(),
    sentScene: SCENE,
    image: new Blob(['png'], { type: 'image/png' }),
    filename: 'still-life.png',
    width: 800,
    height: 600,
    renderMillis: 1500,
    raysPerSecond: 4.2e6,
    ...overrides,
  };
}

describe('renderRecord', () => {
  it('keeps the exact scene sent, its name and samples, and the job figures', () => {
    const record = recordOf(finished(), 3);
    expect(record).toMatchObject({
      number: 3,
      sceneName: 'still-life',
      samples: 32,
      adaptive: false,
      width: 800,
      height: 600,
      renderMillis: 1500,
      raysPerSecond: 4.2e6,
      filename: 'still-life.png',
      thumbnail: null,
    });
    expect(record?.scene).toEqual(SCENE);
    // a copy: a later change to the value sent changes nothing kept
    expect(record?.scene).not.toBe(SCENE);
  });

  it('fills the defaults the server used: 16 samples, adaptive, named "render"', () => {
    const record = recordOf(finished({ sentScene: { objects: [] } }), 1);
    expect(record).toMatchObject({ samples: 16, adaptive: true, sceneName: 'render' });
  });

  it('reads JSON text as its scene, and keeps no record of what is no scene', () => {
    expect(sceneOfSent(JSON.stringify(SCENE))).toEqual(SCENE);
    expect(sceneOfSent('{ not json')).toBeNull();
    expect(sceneOfSent({ objects: [{ type: 'cone' }] })).toBeNull();
    expect(recordOf(finished({ sentScene: 'nope' }), 1)).toBeNull();
  });

  it('names a render by its number, scene, time, size, samples and render time', () => {
    const record = recordOf(finished({ sentScene: { ...SCENE, render: { samples: 16 } } }), 2)!;
    expect(recordName(record, record.finishedAt)).toBe('Render 2: still-life · 14:03:12 · 800 × 600 px · up to 16 spp · 1.5 s');
    expect(formatSamples(64, false)).toBe('64 spp');
  });

  it('writes the date for a render of another day', () => {
    const at = new Date(2025, 4, 1, 9, 5, 7).getTime();
    expect(formatFinished(at, at + 3_600_000)).toBe('09:05:07');
    expect(formatFinished(at, new Date(2025, 4, 2, 9, 0).getTime())).toBe('2025-05-01 09:05');
  });

  it('reads a stored record back, and refuses one that is damaged or of another shape', () => {
    const record = recordOf(finished(), 1)!;
    expect(readRecord(structuredClone({ ...record, image: 'x' }))).toBeNull();
    expect(readRecord({ ...record })).toEqual(record);
    expect(readRecord({ ...record, number: '1' })).toBeNull();
    expect(readRecord({ ...record, scene: { objects: 'none' } })).toBeNull();
    expect(readRecord({ ...record, thumbnail: 'x' })).toBeNull();
    expect(readRecord(null)).toBeNull();
  });
});
