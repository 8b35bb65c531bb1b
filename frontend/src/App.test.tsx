import { formatScene } from './model/formatScene';
import { render, screen, waitFor } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import type { FetchFn } from './api/client';
import { App } from './App';

const SIX_MATERIALS = {
  version: 1,
  name: 'six-materials',
  objects: [{ type: 'sphere', center: [0, 1, 0], radius: 1, material: { type: 'mirror' } }],
};

type Route = (init?: RequestInit) => Response | Promise<Response>;

/** A fetch mock answering the example routes, plus whatever the test adds for /api/render. */
function mockServer(renderRoute?: Route) {
  return vi.fn<FetchFn>(async (url, init) => {
    if (url === '/api/scenes') return Response.json([{ name: 'six-materials' }, { name: 'empty' }]);
    if (url === '/api/scenes/six-materials') return Response.json(SIX_MATERIALS);
    if (url === '/api/render' && renderRoute) return renderRoute(init);
    return new Response('', { status: 404, statusText: 'Not Found' });
  });
}

function renderCalls(fetchFn: ReturnType<typeof mockServer>) {
  return fetchFn.mock.calls.filter(([url]) => url === '/api/render');
}

async function pickSixMaterials(user: ReturnType<typeof userEvent.setup>) {
  await screen.findByRole('option', { name: 'six-materials' });
  await user.selectOptions(screen.getByLabelText('Example scene'), 'six-materials');
  await waitFor(() =>
    expect(screen.getByLabelText('Scene JSON')).toHaveValue(formatScene(SIX_MATERIALS)),
  );
}

describe('App', () => {
  beforeEach(() => {
    let next = 0;
    vi.spyOn(URL, 'createObjectURL').mockImplementation(() => `blob:test/${++next}`);
    vi.spyOn(URL, 'revokeObjectURL').mockImplementation(() => {});
  });

  it('shows the product name', async () => {
    render(<App fetchFn={mockServer()} />);
    expect(screen.getByRole('heading', { name: 'Ray Studio' })).toBeInTheDocument();
    await screen.findByRole('option', { name: 'empty' });
  });

  it('loads a picked example into the editor, pretty-printed', async () => {
    const user = userEvent.setup();
    const fetchFn = mockServer();
    render(<App fetchFn={fetchFn} />);
    await pickSixMaterials(user);
    expect(fetchFn).toHaveBeenCalledWith('/api/scenes/six-materials', expect.anything());
  });

  it('reports invalid JSON locally without calling the server', async () => {
    const user = userEvent.setup();
    const fetchFn = mockServer(() => new Response(''));
    render(<App fetchFn={fetchFn} />);
    await screen.findByRole('option', { name: 'six-materials' });
    await user.type(screen.getByLabelText('Scene JSON'), '{{ "objects": ');
    await user.click(screen.getByRole('button', { name: 'Render' }));

    const alert = screen.getByRole('alert');
    expect(alert).toHaveTextContent('The scene is not valid JSON');
    expect(alert.textContent?.length ?? 0).toBeGreaterThan('The scene is not valid JSON'.length);
    expect(renderCalls(fetchFn)).toHaveLength(0);
  });

  it('lists each field error of a 400 problem response', async () => {
    const user = userEvent.setup();
    const fetchFn = mockServer(
      () =>
        new Response(
          JSON.stringify({
            type: 'about:blank',
            title: 'Invalid scene',
            status: 400,
            detail: '2 fields are invalid',
            errors: [
              { field: 'objects[2].radius', message: 'must be greater than 0' },
              { field: 'image.width', message: 'must be at most 4096' },
            ],
          }),
          { status: 400, headers: { 'Content-Type': 'application/problem+json' } },
        ),
    );
    render(<App fetchFn={fetchFn} />);
    await pickSixMaterials(user);
    await user.click(screen.getByRole('button', { name: 'Render' }));

    const alert = await screen.findByRole('alert');
    expect(alert).toHaveTextContent('Invalid scene');
    expect(alert).toHaveTextContent('2 fields are invalid');
    const items = screen.getAllByRole('listitem').map((item) => item.textContent);
    expect(items).toEqual([
      'objects[2].radius — must be greater than 0',
      'image.width — must be at most 4096',
    ]);
    expect(renderCalls(fetchFn)[0][1]?.body).toBe(formatScene(SIX_MATERIALS));
  });

  it('disables Render while rendering, then shows the image, statistics and download', async () => {
    const user = userEvent.setup();
    let finish: (response: Response) => void = () => {};
    const fetchFn = mockServer(() => new Promise<Response>((resolve) => (finish = resolve)));
    render(<App fetchFn={fetchFn} />);
    await pickSixMaterials(user);
    await user.click(screen.getByRole('button', { name: 'Render' }));

    expect(screen.getByRole('button', { name: 'Render' })).toBeDisabled();
    expect(screen.getByRole('status')).toHaveTextContent('Rendering…');

    finish(
      new Response(new Uint8Array([0x89, 0x50]), {
        headers: {
          'Content-Type': 'image/png',
          'Content-Disposition': 'attachment; filename="six-materials.png"',
          'X-Render-Millis': '850',
          'X-Rays-Per-Second': '12300000',
        },
      }),
    );

    const image = await screen.findByRole('img', { name: 'Rendered scene' });
    expect(image).toHaveAttribute('src', 'blob:test/1');
    expect(screen.getByRole('button', { name: 'Render' })).toBeEnabled();
    expect(screen.queryByText('Rendering…')).not.toBeInTheDocument();
    expect(screen.getByText('850 ms')).toBeInTheDocument();
    expect(screen.getByText('12.3 M rays/s')).toBeInTheDocument();
    const link = screen.getByRole('link', { name: /Download/ });
    expect(link).toHaveAttribute('download', 'six-materials.png');
    expect(link).toHaveAttribute('href', 'blob:test/1');
  });

  it('revokes the previous image when a new render arrives', async () => {
    const user = userEvent.setup();
    const fetchFn = mockServer(
      () => new Response(new Uint8Array([1]), { headers: { 'Content-Type': 'image/jpeg' } }),
    );
    render(<App fetchFn={fetchFn} />);
    await pickSixMaterials(user);
    await user.click(screen.getByRole('button', { name: 'Render' }));
    await screen.findByRole('img', { name: 'Rendered scene' });
    await user.click(screen.getByRole('button', { name: 'Render' }));

    await waitFor(() =>
      expect(screen.getByRole('img', { name: 'Rendered scene' })).toHaveAttribute('src', 'blob:test/2'),
    );
    expect(URL.revokeObjectURL).toHaveBeenCalledWith('blob:test/1');
    expect(screen.getByRole('link', { name: /Download/ })).toHaveAttribute('download', 'render.jpg');
  });

  it('shows a readable error when the server cannot be reached', async () => {
    const user = userEvent.setup();
    const fetchFn = mockServer(() => {
      throw new TypeError('Failed to fetch');
    });
    render(<App fetchFn={fetchFn} />);
    await pickSixMaterials(user);
    await user.click(screen.getByRole('button', { name: 'Render' }));

    const alert = await screen.findByRole('alert');
    expect(alert).toHaveTextContent('Cannot reach the server');
    expect(alert).toHaveTextContent('Failed to fetch');
    expect(screen.getByRole('button', { name: 'Render' })).toBeEnabled();
  });
});
