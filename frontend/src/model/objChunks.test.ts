import { describe, expect, it } from 'vitest';
import { gridObj, TETRAHEDRON_OBJ } from '../test/meshes';
import { ObjError, parseObj, parseObjInChunks } from './obj';

/** A clock that moves `step` ms each time it is read, and counts the pauses taken. */
function fakeClock(step: number) {
  let t = 0;
  const pauses: number[] = [];
  return { now: () => (t += step), pause: async () => void pauses.push(t), pauses };
}

describe('parseObjInChunks', () => {
  it('gives the same mesh as parseObj', async () => {
    const text = gridObj(30);
    const chunked = await parseObjInChunks(text, { linesPerCheck: 50, pause: async () => undefined });
    expect(chunked).toEqual(parseObj(text));
  });

  it('pauses once its time budget is spent, and reports a rising fraction ending at 1', async () => {
    const text = gridObj(40); // 1,681 vertex lines and 1,600 face lines
    const clock = fakeClock(10); // every look at the clock costs 10 ms
    const progress: number[] = [];
    await parseObjInChunks(text, { budgetMs: 25, linesPerCheck: 100, now: clock.now, pause: clock.pause, onProgress: (f) => progress.push(f) });
    // 100 lines per look, a pause after every slice of three looks (10, 20, then 30 >= 25 ms)
    const lines = text.split('\n').length;
    expect(clock.pauses).toHaveLength(Math.ceil(lines / 300) - 1);
    expect(progress).toHaveLength(clock.pauses.length + 1);
    expect(progress.at(-1)).toBe(1);
    for (let i = 1; i < progress.length; i++) expect(progress[i]).toBeGreaterThan(progress[i - 1]);
    expect(progress[0]).toBeGreaterThan(0);
    expect(progress[0]).toBeLessThan(0.15);
  });

  it('names the line of a problem found in a later slice', async () => {
    const text = TETRAHEDRON_OBJ + 'f 1 2 9\n';
    await expect(parseObjInChunks(text, { linesPerCheck: 2, budgetMs: 0, pause: async () => undefined })).rejects.toThrowError(new ObjError(9, 'index 9 out of range (4 vertices so far)'));
  });

  it('stops when aborted', async () => {
    const controller = new AbortController();
    const reading = parseObjInChunks(gridObj(20), { linesPerCheck: 10, budgetMs: 0, signal: controller.signal, pause: async () => controller.abort(new Error('stopped')) });
    await expect(reading).rejects.toThrow('stopped');
  });

  it('keeps every slice of a 200,000-triangle OBJ short', async () => {
    const text = gridObj(317); // 200,978 triangles
    const slices: number[] = [];
    let started = performance.now();
    const parsed = await parseObjInChunks(text, {
      pause: async () => {
        slices.push(performance.now() - started);
        await new Promise((r) => setTimeout(r, 0));
        started = performance.now();
      },
    });
    expect(parsed.triangleCount).toBe(2 * 317 * 317);
    expect(slices.length).toBeGreaterThan(3);
    // a slice is its 25 ms budget plus one look's worth of lines; the median, as a busy test
    // machine may stop the thread within any one slice
    slices.sort((a, b) => a - b);
    expect(slices[Math.floor(slices.length / 2)]).toBeLessThan(100);
  });
});
