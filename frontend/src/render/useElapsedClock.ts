import { useEffect, useState } from 'react';
import type { JobStatus } from '../api/jobs';

/**
 * A job's elapsed time that keeps counting between the server's status events: it starts from
 * the latest status's `elapsedMillis` and, while that status says `running`, ticks on locally.
 * Once the job ends it shows the server's final figure.
 */
export function useElapsedClock(job: JobStatus | null, tickMillis = 100): number {
  const [elapsed, setElapsed] = useState(0);

  useEffect(() => {
    const base = job?.elapsedMillis ?? 0;
    setElapsed(base);
    if (job?.state !== 'running') return undefined;
    const since = Date.now();
    const timer = setInterval(() => setElapsed(base + Date.now() - since), tickMillis);
    return () => clearInterval(timer);
  }, [job, tickMillis]);

  return elapsed;
}
