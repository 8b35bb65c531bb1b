import { useCallback, useEffect, useRef, useState } from 'react';
import { ApiError, fetchScene, fetchSceneList, type FetchFn, type SceneSummary } from '../api/client';
import { formatScene } from '../model/formatScene';

/** The example gallery: its list, the chosen example and the loading state. */
export interface SceneExamples {
  scenes: SceneSummary[];
  selected: string;
  loading: boolean;
  /** Loads an example; resolves with its pretty-printed JSON, or null if superseded. */
  select: (name: string) => Promise<string | null>;
}

/**
 * Loads the example list once on mount and each picked example on demand. A slow answer
 * for an example the user has already moved away from is dropped.
 */
export function useSceneExamples(fetchFn: FetchFn | undefined, onError: (error: ApiError) => void): SceneExamples {
  const [scenes, setScenes] = useState<SceneSummary[]>([]);
  const [selected, setSelected] = useState('');
  const [loading, setLoading] = useState(true);
  const latest = useRef(0);
  const reportError = useRef(onError);
  reportError.current = onError;

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

  const select = useCallback(
    async (name: string) => {
      const request = ++latest.current;
      setSelected(name);
      setLoading(true);
      try {
        const scene = await fetchScene(name, fetchFn);
        return request === latest.current ? formatScene(scene) : null;
      } catch (error) {
        if (request === latest.current) reportError.current(asApiError(error));
        return null;
      } finally {
        if (request === latest.current) setLoading(false);
      }
    },
    [fetchFn],
  );

  return { scenes, selected, loading, select };
}

/** Any thrown value as an ApiError, so the page has one error shape to show. */
export function asApiError(error: unknown): ApiError {
  if (error instanceof ApiError) return error;
  return new ApiError(0, 'Unexpected error', error instanceof Error ? error.message : String(error));
}
