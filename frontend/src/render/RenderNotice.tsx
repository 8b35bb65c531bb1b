import type { ApiError } from '../api/client';
import type { JobApiError, JobStatus } from '../api/jobs';
import { formatSeconds, toPercent } from './format';

/** Props of {@link RenderNotice}. */
export interface RenderNoticeProps {
  /** The last failed request, other than a rejected scene (the error summary shows those). */
  error: JobApiError | null;
  /** The job's latest status, for "failed" and "cancelled". */
  job: JobStatus | null;
}

/** One plain sentence about what went wrong or how the job ended, if it did not finish. */
export function RenderNotice({ error, job }: RenderNoticeProps) {
  if (error && isBusy(error)) {
    const when = error.retryAfter !== undefined ? `in ${formatSeconds(error.retryAfter)}` : 'in a moment';
    return (
      <p className="render-notice render-notice--error" role="alert" data-testid="render-busy">
        The server is busy with other renders. Try again {when}.
      </p>
    );
  }
  if (error) {
    return (
      <p className="render-notice render-notice--error" role="alert" data-testid="render-error">
        {error.title}
        {error.detail ? `: ${error.detail}` : ''}
      </p>
    );
  }
  if (job?.state === 'failed') {
    return (
      <p className="render-notice render-notice--error" role="alert" data-testid="render-failed">
        The render failed{job.error ? `: ${job.error}` : '.'}
      </p>
    );
  }
  if (job?.state === 'cancelled') {
    return (
      <p className="render-notice" role="status" data-testid="render-cancelled">
        Render cancelled at {toPercent(job.progress)}%.
      </p>
    );
  }
  return null;
}

/** True for "come back later" answers: 429 Too Many Requests and 503 Service Unavailable. */
export function isBusy(error: ApiError): boolean {
  return error.status === 429 || error.status === 503;
}
