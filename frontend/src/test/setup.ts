import '@testing-library/jest-dom/vitest';
import { cleanup } from '@testing-library/react';
import { afterEach, beforeEach } from 'vitest';
import { resetSceneStore } from '../store/sceneStore';

// Every test starts from the still life with empty history, and leaves nothing saved.
beforeEach(() => {
  localStorage.clear();
  resetSceneStore();
});

// Vitest runs without globals, so Testing Library cannot register its own cleanup.
afterEach(() => {
  cleanup();
  localStorage.clear();
});
