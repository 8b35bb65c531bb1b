import { useEffect, useState } from 'react';
import { loadAssetBytes } from './useMeshes';

/** An object URL of an asset's bytes (a thumbnail), null until loaded or when it cannot be; revoked when done. */
export function useAssetUrl(id: string | undefined): { url: string | null; error: string | null } {
  const [state, setState] = useState<{ id?: string; url: string | null; error: string | null }>({ url: null, error: null });
  useEffect(() => {
    if (!id) return;
    let url: string | null = null;
    let live = true;
    loadAssetBytes(id).then(
      (bytes) => {
        if (!live) return;
        url = URL.createObjectURL(new Blob([bytes]));
        setState({ id, url, error: null });
      },
      (error: unknown) => live && setState({ id, url: null, error: error instanceof Error ? error.message : String(error) }),
    );
    return () => {
      live = false;
      if (url) URL.revokeObjectURL(url);
    };
  }, [id]);
  return state.id === id ? state : { url: null, error: null };
}
