import { StrictMode } from 'react';
import { createRoot } from 'react-dom/client';
import { App } from './App';
import { startAutosave } from './store/autosave';
import './styles.css';

const root = document.getElementById('root');
if (!root) throw new Error('index.html has no #root element');

// The scene survives a reload: what IndexedDB keeps is put back before the editor shows (at most
// a few seconds; autosave's status says if it could not), then every committed change is kept.
void startAutosave().then(() =>
  createRoot(root).render(
    <StrictMode>
      <App />
    </StrictMode>,
  ),
);
