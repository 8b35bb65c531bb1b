/** The page's one render history, kept in IndexedDB; made on first use (tests pass their own). */
import { indexedDbStorage } from './indexedDbStorage';
import { RenderHistory } from './RenderHistory';

let session: RenderHistory | null = null;

export function sessionRenderHistory(): RenderHistory {
  session ??= new RenderHistory(indexedDbStorage());
  return session;
}
