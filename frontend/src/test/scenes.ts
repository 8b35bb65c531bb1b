/** The example scene files of the repository (`scenes/*.json`), read from disk for tests. */
import { readdirSync, readFileSync } from 'node:fs';
import { resolve } from 'node:path';

/** Vitest runs in `frontend/`, beside `scenes/`. */
export const SCENES_DIR = resolve(process.cwd(), '..', 'scenes') + '/';

/** Every example as [file name, parsed JSON]. */
export function exampleScenes(): [string, unknown][] {
  return readdirSync(SCENES_DIR)
    .filter((f) => f.endsWith('.json'))
    .sort()
    .map((f) => [f, JSON.parse(readFileSync(SCENES_DIR + f, 'utf8')) as unknown]);
}
