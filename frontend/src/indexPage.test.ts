import { readFileSync } from 'node:fs';
import { resolve } from 'node:path';
import { describe, expect, it } from 'vitest';

describe('index.html', () => {
  it('carries its icon inline, so the browser asks the server for no favicon (a 404 before)', () => {
    const html = readFileSync(resolve(process.cwd(), 'index.html'), 'utf8');
    const icon = /<link rel="icon"[^>]*href="([^"]+)"/.exec(html);
    expect(icon?.[1]).toMatch(/^data:image\/svg\+xml,/);
  });
});
