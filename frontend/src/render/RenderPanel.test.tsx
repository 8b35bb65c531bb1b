import { act, screen, waitFor } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import { recordingContext, statusJson, tileJson } from '../test/renderFakes';
import { calls, mockServer, PROBLEM, SCENE, setup } from '../test/panelHarness';
import { RenderPanel } from './RenderPanel';

describe('RenderPanel', () => {
  let canvas: ReturnType<typeof recordingContext>;

  beforeEach(() => {
    let next = 0;
    vi.spyOn(URL, 'createObjectURL').mockImplementation(() => `blob:test/${++next}`);
    vi.spyOn(URL, 'revokeObjectURL').mockImplementation(() => {});
    canvas = recordingContext();
    vi.spyOn(HTMLCanvasElement.prototype, 'getContext').mockImplementation(
      () => canvas.context as unknown as ReturnType<HTMLCanvasElement['getContext']>,
    );
    vi.stubGlobal('createImageBitmap', async () => ({ close: () => {} }));
    return () => vi.unstubAllGlobals();
  });

  it('posts the scene and follows the job it started', async () => {
    const { fetchFn, startRender, onFieldErrors } = setup();
    const source = await startRender();
    const posts = calls(fetchFn, 'POST', '/api/jobs');
    expect(posts).toHaveLength(1);
    expect(JSON.parse(String(posts[0][1]?.body))).toEqual(SCENE);
    expect(source.url).toBe('/api/jobs/k3j/events');
    expect(onFieldErrors).toHaveBeenCalledWith({}, SCENE);
    expect(screen.getByTestId('render-progress')).toHaveAttribute('aria-valuenow', '0');
    expect(screen.getByTestId('cancel-button')).toBeInTheDocument();
  });

  it('advances the progress bar and paints each tile where it belongs', async () => {
    const { startRender } = setup();
    const source = await startRender();
    const element = screen.getByTestId('render-canvas') as HTMLCanvasElement;
    expect([element.width, element.height]).toEqual([64, 32]);
    expect(element).toBeVisible();

    act(() => source.emit('status', statusJson({ state: 'running' })));
    act(() => source.emit('tile', tileJson(32, 0, 0.5)));
    const progress = screen.getByRole('progressbar');
    expect(progress).toHaveAttribute('aria-valuenow', '50');
    expect(progress).toHaveTextContent('50%');
    expect(progress).toHaveTextContent(/Rendering · 50% · \d+ ms/);
    await waitFor(() => expect(canvas.draws).toEqual([expect.objectContaining({ x: 32, y: 0, width: 32, height: 32 })]));

    act(() => source.emit('tile', tileJson(0, 0, 1)));
    expect(progress).toHaveAttribute('aria-valuenow', '100');
    await waitFor(() => expect(canvas.draws).toHaveLength(2));
  });

  it('cancels with DELETE and says so when the job ends', async () => {
    const { fetchFn, startRender, user } = setup();
    const source = await startRender();
    act(() => source.emit('status', statusJson({ state: 'running' })));
    act(() => source.emit('tile', tileJson(0, 0, 0.25)));

    await user.click(screen.getByTestId('cancel-button'));
    await waitFor(() => expect(calls(fetchFn, 'DELETE', '/api/jobs/k3j')).toHaveLength(1));
    expect(screen.getByTestId('cancel-button')).toHaveTextContent('Cancelling…');

    act(() => source.emit('end', statusJson({ state: 'cancelled', progress: 0.25 })));
    expect(source.closed).toBe(true);
    expect(screen.getByTestId('render-cancelled')).toHaveTextContent('Render cancelled at 25%.');
    expect(screen.queryByTestId('cancel-button')).not.toBeInTheDocument();
    expect(screen.queryByTestId('render-image')).not.toBeInTheDocument();
  });

  it('maps a 400 onto field errors and a summary, and clears both on the next start', async () => {
    const problem = {
      title: 'Invalid scene',
      status: 400,
      errors: [
        { field: 'objects[0].radius', message: 'must be greater than 0' },
        { field: 'camera.up', message: 'must not be a zero-length vector' },
      ],
    };
    let reject = true;
    const fetchFn = mockServer({
      'POST /api/jobs': () =>
        reject
          ? new Response(JSON.stringify(problem), { status: 400, headers: PROBLEM })
          : Response.json(statusJson(), { status: 202 }),
    });
    const { onFieldErrors, user, streams } = setup(fetchFn);

    await user.click(screen.getByTestId('render-button'));
    const summary = await screen.findByTestId('error-summary');
    expect(onFieldErrors).toHaveBeenCalledWith({
      'objects[0].radius': 'must be greater than 0',
      'camera.up': 'must not be a zero-length vector',
    }, SCENE);
    expect(summary).toHaveTextContent('Invalid scene: 2 problems');
    // in the inspector's words, the JSON path as a tooltip
    expect(summary).toHaveTextContent('Sphere 1 › Radius: must be greater than 0');
    expect(summary).toHaveTextContent('Camera › Up: must not be a zero-length vector');
    expect(screen.getByText('Sphere 1 › Radius')).toHaveAttribute('title', 'objects[0].radius');
    expect(screen.queryByTestId('render-progress')).not.toBeInTheDocument();
    expect(streams.opened).toHaveLength(0);

    reject = false;
    await user.click(screen.getByTestId('render-button'));
    await waitFor(() => expect(onFieldErrors).toHaveBeenLastCalledWith({}, SCENE));
    expect(screen.queryByTestId('error-summary')).not.toBeInTheDocument();
  });

  it('shows the image, its statistics and the download name when the job is done', async () => {
    const { startRender, fetchFn } = setup();
    const source = await startRender();
    act(() => source.emit('status', statusJson({ state: 'running' })));
    act(() =>
      source.emit('end', statusJson({ state: 'done', progress: 1, elapsedMillis: 1500, raysPerSecond: 4.2e6 })),
    );

    const image = await screen.findByTestId('render-image');
    expect(calls(fetchFn, 'GET', '/api/jobs/k3j/image')).toHaveLength(1);
    expect(image).toHaveAttribute('src', 'blob:test/1');
    const link = screen.getByTestId('download-link');
    expect(link).toHaveAttribute('href', 'blob:test/1');
    expect(link).toHaveAttribute('download', 'still-life.png');
    expect(link).toHaveTextContent('Download still-life.png');
    const stats = screen.getByTestId('render-stats');
    expect(stats).toHaveTextContent('64 × 32 px');
    expect(stats).toHaveTextContent('1.5 s');
    expect(stats).toHaveTextContent('4.2 M rays/s');
    expect(screen.getByRole('progressbar')).toHaveAttribute('aria-valuenow', '100');
    expect(screen.getByTestId('render-canvas')).not.toBeVisible();
    expect(screen.queryByTestId('cancel-button')).not.toBeInTheDocument();
  });

  it('says "Out of date" once the scene differs from the one rendered, and renders again on request', async () => {
    const { startRender, fetchFn, view, onFieldErrors, streams, history } = setup();
    const source = await startRender();
    act(() => source.emit('end', statusJson({ state: 'done', progress: 1 })));
    await screen.findByTestId('render-image');
    expect(screen.queryByText('Out of date')).toBeNull();
    const changed = { ...SCENE, objects: [{ type: 'sphere', radius: 2 }] };
    view.rerender(<RenderPanel scene={changed} onFieldErrors={onFieldErrors} fetchFn={fetchFn} eventSourceFactory={streams.factory} history={history} />);
    expect(screen.getByText('Out of date')).toBeVisible();
    expect(screen.getByRole('img', { name: 'The render' })).toBeInTheDocument();
    await userEvent.setup().click(screen.getByRole('button', { name: 'Render again' }));
    await waitFor(() => expect(calls(fetchFn, 'POST', '/api/jobs')).toHaveLength(2));
    expect(JSON.parse(String(calls(fetchFn, 'POST', '/api/jobs')[1][1]?.body))).toEqual(changed);
    expect(screen.queryByText('Out of date')).toBeNull();
    // the same scene again (a new but equal value) is not out of date
    view.rerender(<RenderPanel scene={structuredClone(changed)} onFieldErrors={onFieldErrors} fetchFn={fetchFn} eventSourceFactory={streams.factory} history={history} />);
    expect(screen.queryByText('Out of date')).toBeNull();
  });

  it('opens the finished image in the full-size viewer; the image is named "The render"', async () => {
    const { startRender, user } = setup();
    const source = await startRender();
    act(() => source.emit('end', statusJson({ state: 'done', progress: 1 })));
    expect(await screen.findByRole('img', { name: 'The render' })).toBeInTheDocument();
    await user.click(screen.getByRole('button', { name: 'Full size' }));
    expect(screen.getByRole('dialog', { name: 'Full-size image still-life.png' })).toBeInTheDocument();
    await user.click(screen.getByRole('button', { name: 'Close' }));
    expect(screen.queryByRole('dialog')).toBeNull();
  });

  it('says when to retry if the server is busy', async () => {
    const fetchFn = mockServer({
      'POST /api/jobs': () =>
        new Response(JSON.stringify({ title: 'Too Many Requests', status: 429 }), {
          status: 429,
          headers: { ...PROBLEM, 'Retry-After': '30' },
        }),
    });
    const { user, onFieldErrors } = setup(fetchFn);
    await user.click(screen.getByTestId('render-button'));
    expect(await screen.findByTestId('render-busy')).toHaveTextContent(
      'The server is busy with other renders. Try again in 30 seconds.',
    );
    expect(onFieldErrors).not.toHaveBeenCalled();
  });

  it('shows why a job failed', async () => {
    const { startRender } = setup();
    const source = await startRender();
    act(() => source.emit('end', statusJson({ state: 'failed', error: 'Out of memory' })));
    expect(screen.getByTestId('render-failed')).toHaveTextContent('The render failed: Out of memory');
    expect(screen.getByRole('progressbar')).toHaveTextContent('Failed');
  });

  it('cancels the running job, and waits for that, before starting another', async () => {
    let id = 0;
    let releaseDelete = () => {};
    const deleted = new Promise<void>((resolve) => {
      releaseDelete = resolve;
    });
    const fetchFn = mockServer({
      'POST /api/jobs': () => Response.json(statusJson({ id: `job${++id}` }), { status: 202 }),
      'DELETE /api/jobs/job1': async () => {
        await deleted;
        return Response.json(statusJson({ id: 'job1', state: 'cancelled' }), { status: 202 });
      },
    });
    const { startRender, streams, user } = setup(fetchFn);
    const first = await startRender();
    act(() => first.emit('status', statusJson({ id: 'job1', state: 'running' })));

    await user.click(screen.getByTestId('render-button'));
    await waitFor(() => expect(calls(fetchFn, 'DELETE', '/api/jobs/job1')).toHaveLength(1));
    expect(first.closed).toBe(true);
    expect(calls(fetchFn, 'POST', '/api/jobs')).toHaveLength(1);
    expect(screen.getByTestId('render-button')).toBeDisabled();

    releaseDelete();
    await waitFor(() => expect(streams.opened).toHaveLength(2));
    const order = fetchFn.mock.calls.map(([url, init]) => `${init?.method ?? 'GET'} ${url}`);
    expect(order).toEqual(['POST /api/jobs', 'DELETE /api/jobs/job1', 'POST /api/jobs']);
    expect(streams.last().url).toBe('/api/jobs/job2/events');

    // A late tile of the old job changes nothing.
    act(() => first.emit('tile', tileJson(0, 0, 0.9)));
    expect(screen.getByRole('progressbar')).toHaveAttribute('aria-valuenow', '0');
  });

  it('asks for the job when the stream is lost, and shows the image if it is done', async () => {
    const fetchFn = mockServer({
      'GET /api/jobs/k3j': () => Response.json(statusJson({ state: 'done', progress: 1, elapsedMillis: 800 })),
    });
    const { startRender } = setup(fetchFn);
    const source = await startRender();
    act(() => source.fail(2));
    expect(await screen.findByTestId('render-image')).toBeInTheDocument();
    expect(screen.queryByTestId('render-error')).not.toBeInTheDocument();
  });
});
