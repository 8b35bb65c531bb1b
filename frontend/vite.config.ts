/// <reference types="vitest/config" />
import { defineConfig } from 'vite';
import react from '@vitejs/plugin-react';

/**
 * Backend address for `npm run dev`; the built page is served by the Java jar itself. The proxy
 * forwards WebSocket upgrades too (`ws`), for the live ray-traced view at /api/preview, with the
 * backend's own Origin (`rewriteWsOrigin`): the server accepts upgrades from its own origin only
 * and refused the dev server's with 403.
 */
const BACKEND = 'http://localhost:8080';

export default defineConfig({
  base: '/',
  plugins: [react()],
  build: {
    outDir: 'dist',
    emptyOutDir: true,
  },
  server: {
    proxy: {
      '/api': { target: BACKEND, changeOrigin: true, ws: true, rewriteWsOrigin: true },
    },
  },
  test: {
    environment: 'happy-dom',
    setupFiles: ['./src/test/setup.ts'],
    restoreMocks: true,
  },
});
