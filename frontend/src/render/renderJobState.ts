/**
 * The render job as a state machine: what the panel knows of the current job, and every event
 * that can change it. Pure: no React, no requests. `useRenderJob` makes the requests and sends
 * the actions; this module alone decides what an action means in each state.
 *
 * Every action about a job names it (by the server's id). An action that makes no sense in the
 * state, or is about a job that is no longer the current one, is ignored: the reducer returns the
 * very same state object, and the hook takes that as "nothing happened" (it starts no request on
 * it, e.g. no second image fetch).
 */
import { isFinalState, type JobApiError, type JobState, type JobStatus } from '../api/jobs';

/** Where the panel is: nothing yet, posting the scene, or the job's own state. */
export type RenderPhase = 'idle' | 'starting' | JobState;

/** A finished render, ready to show and download. */
export interface FinishedImage {
  /** Object URL of the image; the hook revokes it when it is replaced or on unmount. */
  url: string;
  filename: string;
  width: number;
  height: number;
  renderMillis: number;
  raysPerSecond: number | null;
}

/** No job: none started yet, or the last start was refused (`error`) or abandoned. */
export interface Idle {
  kind: 'idle';
  error: JobApiError | null;
}

/** The scene is being posted (once the previous job has been stopped). */
export interface Starting {
  kind: 'starting';
}

/** A queued or running job, followed over its event stream. */
export interface Following {
  kind: 'following';
  job: JobStatus;
  /** 0..1; never steps back. */
  progress: number;
  /** The last failed request about this job (a cancel, a lost stream). */
  error: JobApiError | null;
}

/** As {@link Following}, after the server was asked to stop the job; its end says how it ended. */
export interface Cancelling {
  kind: 'cancelling';
  job: JobStatus;
  progress: number;
  error: JobApiError | null;
}

/** The job ended: done (with its image once fetched), failed or cancelled. */
export interface Finished {
  kind: 'finished';
  job: JobStatus;
  progress: number;
  /** Null until a done job's image has been fetched, and always for a failed or cancelled one. */
  image: FinishedImage | null;
  error: JobApiError | null;
}

export type RenderJobState = Idle | Starting | Following | Cancelling | Finished;

export type RenderJobAction =
  /** Render was pressed: whatever there was is dropped. */
  | { type: 'startRequested' }
  /** The server accepted the scene: the answer of the POST. */
  | { type: 'jobAccepted'; status: JobStatus }
  | { type: 'startRejected'; error: JobApiError }
  /** A `status` event. */
  | { type: 'status'; status: JobStatus }
  /** A `tile` event of the job `jobId`; only its progress matters here (tiles are painted directly). */
  | { type: 'tile'; jobId: string; progress: number }
  /** The `end` event. */
  | { type: 'ended'; status: JobStatus }
  | { type: 'imageFetched'; jobId: string; image: FinishedImage }
  | { type: 'imageFailed'; jobId: string; error: JobApiError }
  /** The stream gave up; `status` is what asking for the job then said (null if that failed too). */
  | { type: 'streamLost'; jobId: string; error: JobApiError; status: JobStatus | null }
  /** Cancel was pressed: abandons a start, or asks the server to stop the job. */
  | { type: 'cancelRequested' }
  /** The answer of the DELETE. */
  | { type: 'cancelAnswered'; status: JobStatus }
  | { type: 'cancelFailed'; jobId: string; error: JobApiError };

export const INITIAL_STATE: RenderJobState = { kind: 'idle', error: null };
const STARTING: Starting = { kind: 'starting' };

/**
 * The state after an action. A final status is the job's end whichever message brings it (a
 * status or end event, the answer of a cancel, the look-up after a lost stream).
 */
export function renderJobReducer(state: RenderJobState, action: RenderJobAction): RenderJobState {
  switch (action.type) {
    case 'startRequested':
      return STARTING;
    case 'jobAccepted':
      if (state.kind !== 'starting') return state;
      return observe({ kind: 'following', job: action.status, progress: 0, error: null }, action.status);
    case 'startRejected':
      return state.kind === 'starting' ? { kind: 'idle', error: action.error } : state;
    case 'status':
    case 'ended':
    case 'cancelAnswered':
      return isFollowing(state, action.status.id) ? observe(state, action.status) : state;
    case 'tile':
      if (!isFollowing(state, action.jobId) || action.progress <= state.progress) return state;
      return { ...state, progress: action.progress };
    case 'streamLost': {
      if (!isFollowing(state, action.jobId)) return state;
      const known = action.status ? observe(state, action.status) : state;
      // a job that has ended is simply finished; otherwise its progress is no longer seen: say so
      return known.kind === 'finished' ? known : { ...known, error: action.error };
    }
    case 'cancelRequested':
      if (state.kind === 'starting') return { kind: 'idle', error: null };
      return state.kind === 'following' ? { ...state, kind: 'cancelling' } : state;
    case 'cancelFailed':
      if (state.kind !== 'cancelling' || state.job.id !== action.jobId) return state;
      return { ...state, kind: 'following', error: action.error };
    case 'imageFetched':
      return awaitsImage(state, action.jobId) ? { ...state, image: action.image } : state;
    case 'imageFailed':
      return awaitsImage(state, action.jobId) ? { ...state, error: action.error } : state;
  }
}

/** What the panel shows of a state. */
export interface RenderJobView {
  phase: RenderPhase;
  job: JobStatus | null;
  progress: number;
  image: FinishedImage | null;
  error: JobApiError | null;
  cancelling: boolean;
}

export function viewOf(state: RenderJobState): RenderJobView {
  switch (state.kind) {
    case 'idle':
      return { phase: 'idle', job: null, progress: 0, image: null, error: state.error, cancelling: false };
    case 'starting':
      return { phase: 'starting', job: null, progress: 0, image: null, error: null, cancelling: false };
    case 'following':
    case 'cancelling':
    case 'finished': {
      const { job, progress, error } = state;
      const image = state.kind === 'finished' ? state.image : null;
      return { phase: job.state, job, progress, image, error, cancelling: state.kind === 'cancelling' };
    }
  }
}

/** The state after a status of the job being followed: finished when it is final. */
function observe(state: Following | Cancelling, status: JobStatus): Following | Cancelling | Finished {
  const progress = status.state === 'done' ? 1 : Math.max(state.progress, status.progress);
  if (isFinalState(status.state)) return { kind: 'finished', job: status, progress, image: null, error: state.error };
  return { ...state, job: status, progress };
}

/** True when the state follows the job `jobId` (queued or running, cancelling or not). */
function isFollowing(state: RenderJobState, jobId: string): state is Following | Cancelling {
  return (state.kind === 'following' || state.kind === 'cancelling') && state.job.id === jobId;
}

/** True when the state is the job `jobId` done and its image not yet here. */
function awaitsImage(state: RenderJobState, jobId: string): state is Finished {
  return state.kind === 'finished' && state.job.id === jobId && state.job.state === 'done' && state.image === null;
}
