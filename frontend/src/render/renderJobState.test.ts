import { describe, expect, it } from 'vitest';
import { ApiError } from '../api/client';
import { JobApiError, parseJobStatus, type JobStatus } from '../api/jobs';
import { statusJson } from '../test/renderFakes';
import {
  INITIAL_STATE,
  renderJobReducer,
  viewOf,
  type FinishedImage,
  type RenderJobAction,
  type RenderJobState,
} from './renderJobState';

function status(overrides: Record<string, unknown> = {}): JobStatus {
  const parsed = parseJobStatus(statusJson(overrides));
  if (!parsed) throw new Error('bad status');
  return parsed;
}

function apiError(status: number, title: string): JobApiError {
  return new JobApiError(new ApiError(status, title));
}

/** The state after the actions, from the initial one. */
function after(...actions: RenderJobAction[]): RenderJobState {
  return actions.reduce(renderJobReducer, INITIAL_STATE);
}

const IMAGE: FinishedImage = { url: 'blob:test/1', filename: 'still-life.png', width: 64, height: 32, renderMillis: 1500, raysPerSecond: null };
const LOST = apiError(0, 'Lost the render progress');

const start: RenderJobAction = { type: 'startRequested' };
const accepted = (overrides = {}): RenderJobAction => ({ type: 'jobAccepted', status: status(overrides) });
const statusOf = (overrides = {}): RenderJobAction => ({ type: 'status', status: status(overrides) });
const tile = (progress: number, jobId = 'k3j'): RenderJobAction => ({ type: 'tile', jobId, progress });
const ended = (overrides = {}): RenderJobAction => ({ type: 'ended', status: status(overrides) });
const imageFetched = (jobId = 'k3j'): RenderJobAction => ({ type: 'imageFetched', jobId, image: IMAGE });

/** A job following, running at 40%. */
const RUNNING = [start, accepted(), statusOf({ state: 'running', progress: 0.4 })];
/** A job done, its image not yet fetched. */
const DONE = [start, accepted(), ended({ state: 'done', progress: 1 })];

/** Expects the action to be ignored: the very same state comes back. */
function expectIgnored(state: RenderJobState, action: RenderJobAction) {
  expect(renderJobReducer(state, action)).toBe(state);
}

describe('renderJobReducer: starting', () => {
  it('starts from any state, dropping the job, its progress, image and error', () => {
    const states = [
      INITIAL_STATE,
      after(start, { type: 'startRejected', error: apiError(429, 'Too Many Requests') }),
      after(start),
      after(...RUNNING),
      after(...RUNNING, { type: 'cancelRequested' }),
      after(...DONE, imageFetched()),
    ];
    for (const state of states) {
      expect(renderJobReducer(state, start)).toEqual({ kind: 'starting' });
      expect(viewOf(renderJobReducer(state, start))).toEqual({ phase: 'starting', job: null, progress: 0, image: null, error: null, cancelling: false });
    }
  });

  it('follows the job the server accepted, at its progress', () => {
    expect(after(start, accepted({ progress: 0.1 }))).toEqual({ kind: 'following', job: status({ progress: 0.1 }), progress: 0.1, error: null });
  });

  it('finishes at once a job accepted as already ended', () => {
    expect(after(start, accepted({ state: 'done', progress: 0.5 }))).toEqual({
      kind: 'finished',
      job: status({ state: 'done', progress: 0.5 }),
      progress: 1,
      image: null,
      error: null,
    });
  });

  it('is idle with the error when the scene is rejected', () => {
    const error = apiError(400, 'Invalid scene');
    expect(after(start, { type: 'startRejected', error })).toEqual({ kind: 'idle', error });
  });

  it('abandons a start on cancel; its answer, accepted or rejected, then changes nothing', () => {
    const abandoned = after(start, { type: 'cancelRequested' });
    expect(abandoned).toEqual({ kind: 'idle', error: null });
    expectIgnored(abandoned, accepted());
    expectIgnored(abandoned, { type: 'startRejected', error: apiError(500, 'Internal Server Error') });
  });

  it('takes an answer to the POST only while starting', () => {
    expectIgnored(INITIAL_STATE, accepted());
    expectIgnored(after(...RUNNING), accepted({ id: 'other' }));
    expectIgnored(after(...DONE), accepted({ id: 'other' }));
    expectIgnored(after(...RUNNING), { type: 'startRejected', error: apiError(429, 'Too Many Requests') });
  });
});

describe('renderJobReducer: following', () => {
  it('keeps the latest status and advances the progress', () => {
    const state = after(...RUNNING);
    expect(state).toEqual({ kind: 'following', job: status({ state: 'running', progress: 0.4 }), progress: 0.4, error: null });
    expect(viewOf(state)).toMatchObject({ phase: 'running', progress: 0.4, cancelling: false });
  });

  it('advances the progress with each tile, keeping the status object (the elapsed clock keys on it)', () => {
    const before = after(...RUNNING);
    const next = renderJobReducer(before, tile(0.6));
    expect(next).toMatchObject({ kind: 'following', progress: 0.6 });
    expect(viewOf(next).job).toBe(viewOf(before).job);
  });

  it('never steps the progress back: neither a tile nor a status with less', () => {
    const state = after(...RUNNING, tile(0.7));
    expectIgnored(state, tile(0.5));
    expectIgnored(state, tile(0.7));
    expect(renderJobReducer(state, statusOf({ state: 'running', progress: 0.2 }))).toMatchObject({ progress: 0.7, job: { progress: 0.2 } });
  });

  it('never steps the progress back over any sequence of statuses and tiles', () => {
    let seed = 12345;
    const random = () => (seed = (seed * 1103515245 + 12345) % 2 ** 31) / 2 ** 31;
    for (let round = 0; round < 200; round++) {
      let state = after(start, accepted());
      let last = 0;
      for (let step = 0; step < 20; step++) {
        const progress = random();
        state = renderJobReducer(state, random() < 0.5 ? tile(progress) : statusOf({ state: 'running', progress }));
        const now = viewOf(state).progress;
        expect(now).toBeGreaterThanOrEqual(last);
        last = now;
      }
    }
  });

  it('ignores a status, tile or end of another job', () => {
    const state = after(...RUNNING);
    expectIgnored(state, statusOf({ id: 'old', state: 'running', progress: 0.9 }));
    expectIgnored(state, tile(0.9, 'old'));
    expectIgnored(state, ended({ id: 'old', state: 'done', progress: 1 }));
  });

  it('ignores a status, tile or end while starting or idle (of a job no longer current)', () => {
    for (const state of [INITIAL_STATE, after(start), after(start, { type: 'cancelRequested' })]) {
      expectIgnored(state, statusOf({ state: 'running' }));
      expectIgnored(state, tile(0.5));
      expectIgnored(state, ended({ state: 'done' }));
    }
  });

  it('finishes on the end: done at 100%, cancelled or failed where it stood', () => {
    expect(after(...DONE)).toMatchObject({ kind: 'finished', job: { state: 'done' }, progress: 1, image: null });
    expect(after(...RUNNING, ended({ state: 'cancelled', progress: 0.3 }))).toMatchObject({ kind: 'finished', job: { state: 'cancelled' }, progress: 0.4 });
    expect(viewOf(after(...RUNNING, ended({ state: 'failed', error: 'Out of memory' })))).toMatchObject({ phase: 'failed', image: null });
  });

  it('takes a final status event as the end', () => {
    expect(after(...RUNNING, statusOf({ state: 'cancelled' }))).toMatchObject({ kind: 'finished', job: { state: 'cancelled' } });
  });

  it('ignores everything of the stream once the job has ended', () => {
    const state = after(...DONE);
    expectIgnored(state, statusOf({ state: 'running', progress: 0.5 }));
    expectIgnored(state, tile(0.5));
    expectIgnored(state, ended({ state: 'done', progress: 1 }));
  });
});

describe('renderJobReducer: the image', () => {
  it('keeps the image of the done job', () => {
    const state = after(...DONE, imageFetched());
    expect(state).toMatchObject({ kind: 'finished', image: IMAGE });
    expect(viewOf(state)).toMatchObject({ phase: 'done', image: IMAGE, progress: 1 });
  });

  it('reports an image that could not be fetched', () => {
    const error = apiError(404, 'Not Found');
    expect(after(...DONE, { type: 'imageFailed', jobId: 'k3j', error })).toMatchObject({ kind: 'finished', image: null, error });
  });

  it('ignores an image arriving after a new start, or one of another job', () => {
    for (const action of [imageFetched(), { type: 'imageFailed', jobId: 'k3j', error: apiError(404, 'Not Found') } as const]) {
      expectIgnored(after(...DONE, start), action);
      expectIgnored(after(...DONE, start, accepted()), action);
    }
    expectIgnored(after(...DONE), imageFetched('old'));
  });

  it('takes no image for a job that is not done, nor a second one', () => {
    expectIgnored(after(...RUNNING), imageFetched());
    expectIgnored(after(...RUNNING, ended({ state: 'cancelled' })), imageFetched());
    expectIgnored(after(...DONE, imageFetched()), imageFetched());
  });
});

describe('renderJobReducer: a lost stream', () => {
  it('finishes a job that has ended meanwhile, without an error', () => {
    const state = after(...RUNNING, { type: 'streamLost', jobId: 'k3j', error: LOST, status: status({ state: 'done', progress: 1 }) });
    expect(state).toMatchObject({ kind: 'finished', job: { state: 'done' }, error: null });
  });

  it('keeps what it learnt of a job still running and reports the lost stream', () => {
    const state = after(...RUNNING, { type: 'streamLost', jobId: 'k3j', error: LOST, status: status({ state: 'running', progress: 0.6 }) });
    expect(state).toMatchObject({ kind: 'following', job: { progress: 0.6 }, progress: 0.6, error: LOST });
  });

  it('reports the lost stream when the job could not be asked for, still cancelling if it was', () => {
    const state = after(...RUNNING, { type: 'cancelRequested' }, { type: 'streamLost', jobId: 'k3j', error: LOST, status: null });
    expect(state).toMatchObject({ kind: 'cancelling', progress: 0.4, error: LOST });
  });

  it('ignores the loss of another job or after the end', () => {
    expectIgnored(after(...RUNNING), { type: 'streamLost', jobId: 'old', error: LOST, status: null });
    expectIgnored(after(...DONE), { type: 'streamLost', jobId: 'k3j', error: LOST, status: null });
  });
});

describe('renderJobReducer: cancelling', () => {
  const cancelling = [...RUNNING, { type: 'cancelRequested' } as const];

  it('marks a job being followed as cancelling', () => {
    expect(after(...cancelling)).toMatchObject({ kind: 'cancelling', progress: 0.4 });
    expect(viewOf(after(...cancelling))).toMatchObject({ phase: 'running', cancelling: true });
  });

  it('ignores cancel when idle, already cancelling, or after the end', () => {
    expectIgnored(INITIAL_STATE, { type: 'cancelRequested' });
    expectIgnored(after(...cancelling), { type: 'cancelRequested' });
    expectIgnored(after(...DONE), { type: 'cancelRequested' });
    expectIgnored(after(...DONE, imageFetched()), { type: 'cancelRequested' });
  });

  it('finishes on a final answer, and keeps cancelling on one still running', () => {
    expect(after(...cancelling, { type: 'cancelAnswered', status: status({ state: 'cancelled', progress: 0.5 }) })).toMatchObject({
      kind: 'finished',
      job: { state: 'cancelled' },
      progress: 0.5,
    });
    expect(after(...cancelling, { type: 'cancelAnswered', status: status({ state: 'running', progress: 0.5 }) })).toMatchObject({
      kind: 'cancelling',
      progress: 0.5,
    });
  });

  it('ignores an answer that comes after the end (the stream was faster)', () => {
    expectIgnored(after(...cancelling, ended({ state: 'done', progress: 1 })), { type: 'cancelAnswered', status: status({ state: 'done', progress: 1 }) });
  });

  it('follows on, with the error, when the cancel fails', () => {
    const error = apiError(500, 'Internal Server Error');
    expect(after(...cancelling, { type: 'cancelFailed', jobId: 'k3j', error })).toMatchObject({ kind: 'following', progress: 0.4, error });
    expectIgnored(after(...cancelling, ended({ state: 'cancelled' })), { type: 'cancelFailed', jobId: 'k3j', error });
    expectIgnored(after(...cancelling, start), { type: 'cancelFailed', jobId: 'k3j', error });
  });
});

describe('viewOf', () => {
  it('shows nothing before the first job, and a refused start as its error', () => {
    expect(viewOf(INITIAL_STATE)).toEqual({ phase: 'idle', job: null, progress: 0, image: null, error: null, cancelling: false });
    const error = apiError(429, 'Too Many Requests');
    expect(viewOf(after(start, { type: 'startRejected', error }))).toMatchObject({ phase: 'idle', job: null, error });
  });
});
