import '@testing-library/jest-dom/vitest';
import { cleanup } from '@testing-library/react';
import { afterEach, beforeEach } from 'vitest';
import { meshCache } from '../hooks/useMeshes';
import { resetSceneStore } from '../store/sceneStore';

// Every test starts from the still life with empty history and no cached meshes, and leaves nothing saved.
beforeEach(() => {
  localStorage.clear();
  sessionStorage.clear();
  resetSceneStore();
  meshCache.clear();
});

// Vitest runs without globals, so Testing Library cannot register its own cleanup.
afterEach(() => {
  cleanup();
  localStorage.clear();
  sessionStorage.clear();
});
