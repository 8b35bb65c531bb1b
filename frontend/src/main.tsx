import { StrictMode } from 'react';
import { createRoot } from 'react-dom/client';
import { App } from './App';
import { persistSceneStore } from './store/sceneStore';
import './styles.css';

const root = document.getElementById('root');
if (!root) throw new Error('index.html has no #root element');

// The scene survives a reload: every committed change is saved to localStorage.
persistSceneStore();

createRoot(root).render(
  <StrictMode>
    <App />
  </StrictMode>,
);
