import { useCallback, useState } from 'react';
import { renderScene, type FetchFn } from './api/client';
import { ErrorPanel, type DisplayError } from './components/ErrorPanel';
import { Header } from './components/Header';
import { RenderButton } from './components/RenderButton';
import { RenderView, type RenderedImage } from './components/RenderView';
import { SceneEditor } from './components/SceneEditor';
import { ScenePicker } from './components/ScenePicker';
import { asApiError, useSceneExamples } from './hooks/useSceneExamples';
import { useObjectUrl } from './hooks/useObjectUrl';

/** Props of {@link App}. */
export interface AppProps {
  /** The fetch used for every request; the browser's by default, a mock in tests. */
  fetchFn?: FetchFn;
}

/** The first page of Ray Studio: pick or edit a scene on the left, render it on the right. */
export function App({ fetchFn }: AppProps) {
  const [text, setText] = useState('');
  const [error, setError] = useState<DisplayError | null>(null);
  const [rendering, setRendering] = useState(false);
  const [stats, setStats] = useState<Omit<RenderedImage, 'url'> | null>(null);
  const [imageUrl, setImage] = useObjectUrl();
  const examples = useSceneExamples(fetchFn, setError);

  const pickExample = useCallback(
    async (name: string) => {
      setError(null);
      const json = await examples.select(name);
      if (json !== null) setText(json);
    },
    [examples],
  );

  const render = useCallback(async () => {
    try {
      JSON.parse(text);
    } catch (parseError) {
      const message = parseError instanceof Error ? parseError.message : String(parseError);
      setError({ title: 'The scene is not valid JSON', detail: message });
      return;
    }
    setError(null);
    setRendering(true);
    try {
      const output = await renderScene(text, fetchFn);
      setImage(output.image);
      setStats({
        filename: output.filename,
        renderMillis: output.renderMillis,
        raysPerSecond: output.raysPerSecond,
      });
    } catch (renderError) {
      setError(asApiError(renderError));
    } finally {
      setRendering(false);
    }
  }, [text, fetchFn, setImage]);

  const image = imageUrl && stats ? { url: imageUrl, ...stats } : null;

  return (
    <div className="app">
      <Header title="Ray Studio" />
      <main className="app-main">
        <section className="panel panel--editor" aria-label="Scene">
          <ScenePicker
            scenes={examples.scenes}
            selected={examples.selected}
            loading={examples.loading}
            onSelect={pickExample}
          />
          <SceneEditor value={text} onChange={setText} />
          <RenderButton rendering={rendering} onRender={render} />
        </section>
        <section className="panel panel--result" aria-label="Result">
          <ErrorPanel error={error} />
          <RenderView image={image} />
        </section>
      </main>
    </div>
  );
}
