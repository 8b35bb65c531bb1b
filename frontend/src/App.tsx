import { lazy, Suspense, useCallback, useState } from 'react';
import type { FetchFn } from './api/client';
import { AutosaveNotice } from './components/AutosaveNotice';
import { FieldErrorsProvider } from './components/fieldErrors';
import { ImportProgress } from './components/ImportProgress';
import { Inspector } from './components/Inspector';
import { JsonTab } from './components/JsonTab';
import { ProblemList } from './components/ProblemList';
import { RenderPanel } from './render/RenderPanel';
import { ShortcutsHelp } from './components/ShortcutsHelp';
import { SignInDialog } from './components/SignInDialog';
import { StageDropZone } from './components/StageDropZone';
import { Toolbar } from './components/Toolbar';
import { useEditorShortcuts } from './hooks/useEditorShortcuts';
import { useAssetsOnServer, useMeshFiles } from './hooks/useMeshes';
import { useSceneErrors } from './hooks/useSceneErrors';
import { ImportContext } from './import/ImportContext';
import { useImport } from './import/useImport';
import { usePanels } from './hooks/usePanels';
import type { Scene } from './model/types';
import { useDraftErrors } from './store/draftErrors';
import { useSceneStore } from './store/sceneStore';
import { SideView } from './views/SideView';
import { TopView } from './views/TopView';

/** Props of {@link App}. */
export interface AppProps {
  /** The fetch used for every request; the browser's by default, a mock in tests. */
  fetchFn?: FetchFn;
}

type StageTab = 'preview' | 'render' | 'json';

// three.js is most of the page's weight: load the preview in its own chunk.
const Preview3D = lazy(() => import('./views/Preview3D').then((m) => ({ default: m.Preview3D })));

/**
 * The scene editor, built around the image: the toolbar on top; in the centre the stage (the 3D
 * preview or live ray-traced view, the final render, or the JSON) with Render and Cancel always in
 * its bar; the top and side views on the left and the inspector on the right, each of which can be
 * hidden (the views start hidden on narrow windows).
 */
export function App({ fetchFn }: AppProps) {
  const [message, setMessage] = useState<string | null>(null);
  const fieldErrors = useSceneErrors();
  const [tab, setTab] = useState<StageTab>('preview');
  const [panels, setPanels] = usePanels();
  const unapplied = useDraftErrors((s) => s.errors);
  const scene = useSceneStore((s) => s.scene);
  const documentId = useSceneStore((s) => s.documentId);
  const report = useSceneStore((s) => s.reportServerErrors);
  const onRenderErrors = useCallback((errors: Record<string, string>, sent: unknown) => report('render', sent as Scene, errors), [report]);
  const onLiveErrors = useCallback(
    (errors: Record<string, string>) => report('live', useSceneStore.getState().preview ?? useSceneStore.getState().scene, errors),
    [report],
  );
  const showRender = useCallback(() => setTab('render'), []);
  const [help, setHelp] = useState(false);
  const closeHelp = useCallback(() => setHelp(false), []);
  useEditorShortcuts(() => setHelp((shown) => !shown));
  const importFiles = useImport(fetchFn, setMessage);
  useMeshFiles(fetchFn);
  useAssetsOnServer(fetchFn);

  const tabButton = (id: StageTab, label: string) => (
    <button type="button" role="tab" id={`tab-${id}`} aria-selected={tab === id} aria-controls={`panel-${id}`} onClick={() => setTab(id)}>
      {label}
    </button>
  );
  const tabs = (
    <div role="tablist" aria-label="Stage" className="tabs">
      {tabButton('preview', '3D preview')}
      {tabButton('render', 'Image')}
      {tabButton('json', 'JSON')}
    </div>
  );
  const layout = `studio-main${panels.views ? '' : ' no-views'}${panels.inspector ? '' : ' no-inspector'}`;
  return (
    <FieldErrorsProvider errors={fieldErrors}>
      <ImportContext.Provider value={importFiles}>
        <div className="studio">
          <header>
            <Toolbar fetchFn={fetchFn} onMessage={setMessage} panels={panels} onPanels={setPanels} onHelp={() => setHelp(true)} onImport={(files) => void importFiles(files)} />
          </header>
          {help && <ShortcutsHelp onClose={closeHelp} />}
          <SignInDialog />
          <AutosaveNotice />
          <ImportProgress />
          {message && (
            <div className="studio-message" role="alert">
              <pre>{message}</pre>
              <button type="button" className="small" onClick={() => setMessage(null)}>
                Dismiss
              </button>
            </div>
          )}
          <main className={layout}>
            <div className="studio-views" hidden={!panels.views}>
              <TopView />
              <SideView />
            </div>
            <StageDropZone className="studio-centre" onFiles={(files) => void importFiles(files)}>
              <RenderPanel
                key={documentId}
                scene={scene}
                onFieldErrors={onRenderErrors}
                fetchFn={fetchFn}
                tabs={tabs}
                showingRender={tab === 'render'}
                onRenderStarted={showRender}
                unapplied={unapplied}
              >
                <div role="tabpanel" id="panel-preview" aria-labelledby="tab-preview" hidden={tab !== 'preview'} className="tab-panel">
                  <Suspense fallback={<p className="hint">Loading the 3D preview…</p>}>
                    <Preview3D shown={tab === 'preview'} onFieldErrors={onLiveErrors} />
                  </Suspense>
                </div>
                <div role="tabpanel" id="panel-json" aria-labelledby="tab-json" hidden={tab !== 'json'} className="tab-panel">
                  {tab === 'json' && <JsonTab />}
                </div>
              </RenderPanel>
            </StageDropZone>
            <div className="studio-inspector" hidden={!panels.inspector}>
              <h2 className="visually-hidden">Scene and selection</h2>
              <ProblemList />
              <Inspector />
            </div>
          </main>
        </div>
      </ImportContext.Provider>
    </FieldErrorsProvider>
  );
}
