/**
 * The API's types (openapi.gen.ts) are what openapi-typescript generates from the server's OpenAPI
 * document (openapi.json, kept equal to what the server publishes by the server's
 * OpenApiEditorCopyTest). After a change to the API: rewrite openapi.json (see that test), then
 * `npm run gen:api`.
 */
import { spawnSync } from 'node:child_process';
import { createRequire } from 'node:module';
import { dirname, resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

const require = createRequire(import.meta.url);
const cli = resolve(dirname(require.resolve('openapi-typescript/package.json')), 'bin/cli.js');

describe('openapi.gen.ts', () => {
  it('is what openapi-typescript generates from openapi.json (npm run gen:api)', () => {
    // the same command as npm run gen:api, with --check: it compares instead of writing
    const run = spawnSync(process.execPath, [cli, 'src/api/openapi.json', '-o', 'src/api/openapi.gen.ts', '--check'], {
      cwd: process.cwd(),
      encoding: 'utf8',
    });
    expect(run.status, `openapi.gen.ts is out of date: run npm run gen:api in frontend/\n${run.stdout}${run.stderr}`).toBe(0);
  }, 30_000);
});
