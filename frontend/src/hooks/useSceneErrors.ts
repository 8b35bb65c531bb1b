import { useMemo } from 'react';
import { plainMessage } from '../components/fieldWords';
import { sceneProblems } from '../model/sceneRules';
import { mergeErrors, standingErrors, type FieldErrors } from '../model/standingErrors';
import { useDraftErrors } from '../store/draftErrors';
import { selectDisplayScene, useSceneStore } from '../store/sceneStore';

/**
 * The messages every field shows, by JSON path: text a field refused (not in the scene), the
 * editor's own checks of the scene on screen, then the server's refusals that still stand (their
 * fields unchanged since), in the editor's words.
 */
export function useSceneErrors(): FieldErrors {
  const scene = useSceneStore(selectDisplayScene);
  const server = useSceneStore((s) => s.serverErrors);
  const drafts = useDraftErrors((s) => s.errors);
  return useMemo(() => {
    const standing = Object.values(server).map((r) => (r ? standingErrors(r.errors, r.scene, scene) : {}));
    const merged = mergeErrors(sceneProblems(scene), drafts, ...standing);
    return Object.fromEntries(Object.entries(merged).map(([path, message]) => [path, plainMessage(scene, message)]));
  }, [scene, server, drafts]);
}
