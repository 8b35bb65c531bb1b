import { useCallback, useEffect, useRef, useState } from 'react';

/**
 * Holds one object URL at a time: setting a new blob revokes the previous URL, and
 * unmounting revokes the last one.
 */
export function useObjectUrl(): [string | null, (blob: Blob | null) => string | null] {
  const [url, setUrl] = useState<string | null>(null);
  const current = useRef<string | null>(null);

  const replace = useCallback((blob: Blob | null) => {
    if (current.current) URL.revokeObjectURL(current.current);
    current.current = blob ? URL.createObjectURL(blob) : null;
    setUrl(current.current);
    return current.current;
  }, []);

  useEffect(
    () => () => {
      if (current.current) URL.revokeObjectURL(current.current);
    },
    [],
  );

  return [url, replace];
}
