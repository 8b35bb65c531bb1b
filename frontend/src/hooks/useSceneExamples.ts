import { useCallback, useEffect, useLayoutEffect, useRef, useState } from 'react';
import { ApiError, fetchScene, fetchSceneList, type FetchFn, type SceneSummary } from '../api/client';

/** The example gallery: its list, whether it is loading, and a loader for one example. */
export interface SceneExamples {
  scenes: SceneSummary[];
  loading: boolean;
  /** Loads an example; resolves with its parsed JSON, or null if it failed or was superseded. */
  load: (name: string) => Promise<unknown | null>;
}

/**
 * Loads the example list once on mount and each picked example on demand. A slow answer
 * for an example the user has already moved away from is dropped.
 */
export function useSceneExamples(fetchFn: FetchFn | undefined, onError: (error: ApiError) => void): SceneExamples {
  const [scenes, setScenes] = useState<SceneSummary[]>([]);
  const [loading, setLoading] = useState(true);
  const latest = useRef(0);
  const reportError = useRef(onError);
  useLayoutEffect(() => {
    reportError.current = onError;
  });

  useEffect(() => {
    let live = true;
    fetchSceneList(fetchFn)
      .then((list) => live && setScenes(list))
      .catch((error: unknown) => live && reportError.current(asApiError(error)))
      .finally(() => live && setLoading(false));
    return () => {
      live = false;
    };
  }, [fetchFn]);

  const load = useCallback(
    async (name: string) => {
      const request = ++latest.current;
      try {
        const scene = await fetchScene(name, fetchFn);
        return request === latest.current ? scene : null;
      } catch (error) {
        if (request === latest.current) reportError.current(asApiError(error));
        return null;
      }
    },
    [fetchFn],
  );

  return { scenes, loading, load };
}

/** Any thrown value as an ApiError, so the page has one error shape to show. */
export function asApiError(error: unknown): ApiError {
  if (error instanceof ApiError) return error;
  return new ApiError(0, 'Unexpected error', error instanceof Error ? error.message : String(error));
}
