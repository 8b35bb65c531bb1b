import { act, fireEvent, render, screen, waitFor, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import type { FetchFn } from './api/client';
import { App } from './App';
import { assetIdOf } from './model/assetHash';
import { STARTER_SCENE } from './model/starterScene';
import { gridObj } from './test/meshes';
import { useSceneStore } from './store/sceneStore';

const store = () => useSceneStore.getState();

const SIX_MATERIALS = {
  version: 1,
  name: 'six-materials',
  objects: [{ type: 'sphere', center: [0, 1, 0], radius: 1, material: { type: 'mirror' } }],
};

type Route = (init?: RequestInit) => Response | Promise<Response>;

/** A fetch mock answering the example routes, plus any "METHOD path" route a test adds. */
function mockServer(routes: Record<string, Route> = {}) {
  return vi.fn<FetchFn>(async (url, init) => {
    const route = routes[`${init?.method ?? 'GET'} ${url}`];
    if (route) return route(init);
    if (url === '/api/scenes') return Response.json([{ name: 'six-materials' }, { name: 'still-life' }]);
    if (url === '/api/scenes/six-materials') return Response.json(SIX_MATERIALS);
    return new Response('', { status: 404, statusText: 'Not Found' });
  });
}

async function renderApp(fetchFn = mockServer()) {
  const utils = render(<App fetchFn={fetchFn} />);
  await waitFor(() => expect(fetchFn).toHaveBeenCalledWith('/api/scenes', expect.anything()));
  return utils;
}

describe('App', () => {
  beforeEach(() => {
    let next = 0;
    vi.spyOn(URL, 'createObjectURL').mockImplementation(() => `blob:test/${++next}`);
    vi.spyOn(URL, 'revokeObjectURL').mockImplementation(() => {});
  });

  it('lays out toolbar, both views, the 3D preview, the render area and the inspector', async () => {
    await renderApp();
    expect(screen.getByRole('heading', { name: 'Ray Studio' })).toBeInTheDocument();
    for (const name of ['New', 'Save', 'Undo', 'Redo', 'Add sphere', 'Add box', 'Add plane', 'Add light']) {
      expect(screen.getByRole('button', { name })).toBeInTheDocument();
    }
    expect(screen.getByTestId('top-view')).toBeInTheDocument();
    expect(screen.getByTestId('side-view')).toBeInTheDocument();
    // the 3D preview is loaded lazily (three.js): on a loaded machine that can take more than the default 1 s
    expect(await screen.findByTestId('preview-3d', {}, { timeout: 10_000 })).toBeInTheDocument();
    expect(screen.getByRole('complementary', { name: 'Inspector' })).toBeInTheDocument();
    expect(screen.getByRole('button', { name: 'Render' })).toBeInTheDocument();
    expect(within(screen.getByTestId('top-view')).getAllByTestId(/^object-/)).toHaveLength(STARTER_SCENE.objects.length);
  }, 20_000);

  it('hides and shows the 2D views and the inspector, and follows the window until the user chooses', async () => {
    const user = userEvent.setup();
    await renderApp();
    const views = screen.getByTestId('top-view').closest('.studio-views')!;
    const shown = window.innerWidth >= 1280;
    expect(views.hasAttribute('hidden')).toBe(!shown);
    await user.click(screen.getByRole('button', { name: '2D views' }));
    expect(views.hasAttribute('hidden')).toBe(shown);
    act(() => window.dispatchEvent(new Event('resize')));
    expect(views.hasAttribute('hidden')).toBe(shown); // the user's choice stands
    await user.click(screen.getByRole('button', { name: 'Inspector' }));
    expect(screen.getByRole('complementary', { name: 'Inspector', hidden: true }).closest('.studio-inspector')).toHaveAttribute('hidden');
  });

  it('adds a sphere, selected in both views and the inspector; Undo and Redo buttons', async () => {
    const user = userEvent.setup();
    await renderApp();
    await user.click(screen.getByTestId('add-sphere'));
    const index = STARTER_SCENE.objects.length;
    for (const view of ['top-view', 'side-view']) {
      expect(within(screen.getByTestId(view)).getByTestId(`object-${index}`)).toHaveAttribute('data-selected', 'true');
    }
    expect(screen.getByRole('heading', { name: `Sphere ${index + 1}` })).toBeInTheDocument();
    expect(screen.getByLabelText('Center x')).toHaveAttribute('data-field', `objects[${index}].center[0]`);
    await user.click(screen.getByRole('button', { name: 'Undo' }));
    expect(store().scene.objects).toHaveLength(index);
    expect(screen.getByRole('button', { name: 'Undo' })).toBeDisabled();
    await user.click(screen.getByRole('button', { name: 'Redo' }));
    expect(store().scene.objects).toHaveLength(index + 1);
  });

  it('deletes with the Delete key, undoes with Ctrl+Z, redoes with Ctrl+Shift+Z and Ctrl+Y', async () => {
    const user = userEvent.setup();
    await renderApp();
    act(() => store().select({ kind: 'object', index: 0 }));
    await user.keyboard('{Delete}');
    expect(store().scene.objects).toHaveLength(STARTER_SCENE.objects.length - 1);
    await user.keyboard('{Control>}z{/Control}');
    expect(store().scene).toEqual(STARTER_SCENE);
    await user.keyboard('{Control>}{Shift>}z{/Shift}{/Control}');
    expect(store().scene.objects).toHaveLength(STARTER_SCENE.objects.length - 1);
    await user.keyboard('{Control>}z{/Control}{Control>}y{/Control}');
    expect(store().scene.objects).toHaveLength(STARTER_SCENE.objects.length - 1);
  });

  it('leaves Delete alone while typing in a field', async () => {
    const user = userEvent.setup();
    await renderApp();
    act(() => store().select({ kind: 'object', index: 1 }));
    await user.click(screen.getByLabelText('Radius'));
    await user.keyboard('{Delete}');
    expect(store().scene.objects).toHaveLength(STARTER_SCENE.objects.length);
  });

  it('commits a half-typed field when the user moves on to a view', async () => {
    const user = userEvent.setup();
    await renderApp();
    act(() => store().select({ kind: 'object', index: 1 }));
    const radius = screen.getByLabelText('Radius');
    await user.clear(radius);
    await user.type(radius, '0.9');
    expect(store().scene.objects[1]).toMatchObject({ radius: 0.5 });
    const svg = screen.getByTestId('top-view');
    fireEvent.pointerDown(svg, { clientX: 3, clientY: 3, button: 0, pointerId: 7 });
    fireEvent.pointerUp(svg, { clientX: 3, clientY: 3, pointerId: 7 });
    expect(store().scene.objects[1]).toMatchObject({ radius: 0.9 });
    expect(store().past).toHaveLength(1);
  });

  it('says what is wrong with a file that is not a scene, and keeps the scene', async () => {
    const user = userEvent.setup();
    await renderApp();
    const bad = new File(['{ "objects": [ { "type": "cone" } ] }'], 'bad.json', { type: 'application/json' });
    await user.upload(screen.getByLabelText('Open scene file'), bad);
    const alert = await screen.findByRole('alert');
    expect(alert).toHaveTextContent('Cannot open bad.json');
    expect(alert).toHaveTextContent('objects[0].type');
    expect(store().scene).toEqual(STARTER_SCENE);

    const broken = new File(['{ nope'], 'broken.json', { type: 'application/json' });
    await user.upload(screen.getByLabelText('Open scene file'), broken);
    await waitFor(() => expect(screen.getByRole('alert')).toHaveTextContent('not valid JSON'));
  });

  it('opens a scene file', async () => {
    const user = userEvent.setup();
    await renderApp();
    const good = new File([JSON.stringify(SIX_MATERIALS)], 'six.json', { type: 'application/json' });
    await user.upload(screen.getByLabelText('Open scene file'), good);
    await waitFor(() => expect(store().scene).toEqual(SIX_MATERIALS));
    expect(store().past).toHaveLength(1);
  });

  it('saves the scene as NAME.json', async () => {
    const user = userEvent.setup();
    const click = vi.spyOn(HTMLAnchorElement.prototype, 'click').mockImplementation(() => {});
    await renderApp();
    await user.click(screen.getByRole('button', { name: 'Save' }));
    expect(click).toHaveBeenCalledTimes(1);
    const link = click.mock.contexts[0] as HTMLAnchorElement;
    expect(link.download).toBe('still-life.json');
    const blob = vi.mocked(URL.createObjectURL).mock.calls[0][0] as Blob;
    expect(JSON.parse(await blob.text())).toEqual(STARTER_SCENE);
  });

  it('shows the keyboard shortcuts on ? and on the toolbar button; Escape closes them', async () => {
    const user = userEvent.setup();
    await renderApp();
    await user.keyboard('?');
    const dialog = screen.getByRole('dialog', { name: 'Keyboard shortcuts' });
    expect(dialog).toHaveTextContent('Move / rotate / scale handles in the 3D preview');
    expect(dialog).toHaveTextContent('Ctrl+C / Ctrl+V');
    await user.keyboard('{Escape}');
    expect(screen.queryByRole('dialog', { name: 'Keyboard shortcuts' })).toBeNull();
    store().select({ kind: 'camera' });
    await user.click(screen.getByRole('button', { name: 'Keyboard shortcuts' }));
    expect(screen.getByRole('dialog', { name: 'Keyboard shortcuts' })).toBeInTheDocument();
    await user.keyboard('{Escape}');
    expect(store().selection).toEqual({ kind: 'camera' }); // Escape closed the panel only
  });

  it('loads an example from the gallery, and New starts a blank scene', async () => {
    const user = userEvent.setup();
    const fetchFn = mockServer();
    await renderApp(fetchFn);
    await user.click(screen.getByText('Examples'));
    await user.click(await screen.findByRole('button', { name: 'six-materials' }));
    await waitFor(() => expect(store().scene).toEqual(SIX_MATERIALS));
    await user.click(screen.getByRole('button', { name: 'New' }));
    expect(store().scene.objects).toEqual([]);
    expect(store().past).toHaveLength(2);
  });

  it('keeps the JSON tab and the store in step both ways', async () => {
    const user = userEvent.setup();
    await renderApp();
    await user.click(screen.getByRole('tab', { name: 'JSON' }));
    const text = screen.getByLabelText('Scene JSON') as HTMLTextAreaElement;
    expect(JSON.parse(text.value)).toEqual(STARTER_SCENE);
    act(() => store().setName('renamed'));
    expect(JSON.parse(text.value).name).toBe('renamed');

    fireEvent.change(text, { target: { value: '{ "objects": 3 }' } });
    expect(screen.getByRole('alert')).toHaveTextContent('objects: must be a list');
    expect(screen.getByRole('button', { name: 'Apply JSON' })).toBeDisabled();
    fireEvent.change(text, { target: { value: JSON.stringify(SIX_MATERIALS) } });
    await user.click(screen.getByRole('button', { name: 'Apply JSON' }));
    expect(store().scene).toEqual(SIX_MATERIALS);
  });

  it('shows the server’s field errors next to their inputs and in a list', async () => {
    const user = userEvent.setup();
    const problem = {
      title: 'Invalid scene',
      status: 400,
      detail: '2 problems',
      errors: [
        { field: 'objects[1].radius', message: 'must be greater than 0' },
        { field: 'image.width', message: 'must be at most 4096' },
      ],
    };
    const bad = () => new Response(JSON.stringify(problem), { status: 400, headers: { 'Content-Type': 'application/problem+json' } });
    await renderApp(mockServer({ 'POST /api/jobs': bad, 'POST /api/render': bad }));
    await user.click(screen.getByRole('button', { name: 'Render' }));
    const list = await screen.findByRole('region', { name: 'Problems' });
    expect(list).toHaveTextContent('Sphere 2 › Radius: must be greater than 0');
    expect(screen.getByLabelText('Width (px)')).toHaveAccessibleDescription('must be at most 4096');
    expect(screen.getByLabelText('Width (px)')).toHaveAttribute('aria-invalid', 'true');
    await user.click(within(list).getByRole('button', { name: 'Sphere 2 › Radius' }));
    expect(store().selection).toEqual({ kind: 'object', index: 1 });
    const radius = screen.getByLabelText('Radius');
    expect(radius).toHaveAccessibleDescription('must be greater than 0');
    expect(radius).toHaveAttribute('aria-invalid', 'true');

    // an error goes as soon as its field changes; the others stay
    await user.clear(radius);
    await user.type(radius, '0.7{Enter}');
    expect(radius).not.toHaveAttribute('aria-invalid');
    expect(list).not.toHaveTextContent('Radius');
    expect(list).toHaveTextContent('Image › Width: must be at most 4096');

    // New forgets the old scene's errors
    await user.click(screen.getByRole('button', { name: 'New' }));
    expect(screen.queryByRole('region', { name: 'Problems' })).toBeNull();
    expect(screen.getByLabelText('Width (px)')).not.toHaveAttribute('aria-invalid');
  });

  it('refuses to render while a field holds text it refused, and says the stage is not the scene as typed', async () => {
    const user = userEvent.setup();
    const fetchFn = mockServer();
    await renderApp(fetchFn);
    act(() => store().select({ kind: 'object', index: 1 }));
    const radius = screen.getByLabelText('Radius');
    await user.clear(radius);
    await user.type(radius, '-1{Enter}');
    expect(store().scene.objects[1]).toMatchObject({ radius: 0.5 }); // not in the scene
    expect(await screen.findByTestId('not-as-typed')).toHaveTextContent('Not as typed');
    await user.click(screen.getByRole('button', { name: 'Render' }));
    const summary = await screen.findByTestId('error-summary');
    expect(summary).toHaveTextContent('Not rendered: fix these fields first');
    expect(summary).toHaveTextContent('Sphere 2 › Radius');
    expect(fetchFn.mock.calls.some(([url]) => url === '/api/jobs' || url === '/api/render')).toBe(false);
    expect(await screen.findByRole('region', { name: 'Problems' })).toHaveTextContent('Sphere 2 › Radius');

    // fixed: the refusal goes, and Render sends the scene
    await user.clear(radius);
    await user.type(radius, '0.8{Enter}');
    expect(screen.queryByTestId('not-as-typed')).toBeNull();
    expect(screen.queryByTestId('error-summary')).toBeNull();
  });

  it('warns before Render about what the server would refuse: an opened radius of -1, Up along the view', async () => {
    await renderApp();
    act(() => store().loadScene({ camera: { position: [0, 5, 0], lookAt: [0, 0, 0], up: [0, 1, 0] }, objects: [{ type: 'sphere', radius: -1 }] }));
    const list = await screen.findByRole('region', { name: 'Problems' });
    expect(list).toHaveTextContent('Sphere 1 › Radius: must be greater than 0');
    expect(list).toHaveTextContent("Camera › Up: is parallel to the view direction (Look at − Position); the camera's roll is undefined");
    expect(screen.getByLabelText('Up y')).toHaveAttribute('aria-invalid', 'true');
    act(() => store().setCamera({ up: [0, 0, -1] }));
    expect(list).not.toHaveTextContent('Camera');
    expect(screen.getByLabelText('Up y')).not.toHaveAttribute('aria-invalid');
  });

  it('adds a mesh from an OBJ file: uploaded once, by its id, on the floor, about 2 m across, selected, one undo step', async () => {
    const user = userEvent.setup();
    const obj = gridObj(10, 0.5); // 0.5 m square: scaled by 4
    const id = await assetIdOf(new Blob([obj]));
    const uploaded: string[] = [];
    const fetchFn = mockServer({
      [`HEAD /api/assets/${id}`]: () => new Response(null, { status: 404 }),
      'POST /api/assets': (init) => {
        uploaded.push(new Headers(init?.headers).get('Content-Type')!);
        return Response.json({ id, bytes: obj.length, mediaType: 'model/obj' }, { status: 201 });
      },
    });
    await renderApp(fetchFn);
    expect(screen.getByRole('button', { name: 'Add mesh' })).toBeInTheDocument();
    await user.upload(screen.getByTestId('add-mesh'), new File(['v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3 4\n'], 'bad.obj'));
    expect(await screen.findByRole('alert')).toHaveTextContent('Cannot import bad.obj: it is not a usable OBJ mesh (line 4: index 4 out of range (3 vertices so far))');
    await user.click(screen.getByRole('button', { name: 'Dismiss' }));
    await user.upload(screen.getByTestId('add-mesh'), new File([obj], 'grid.obj'));
    const index = STARTER_SCENE.objects.length;
    await waitFor(() => expect(store().scene.objects[index]).toEqual({ type: 'mesh', name: 'grid', asset: id, position: expect.any(Array), scale: 4, rotation: [0, 0, 0], material: { type: 'plastic', color: '#4f8fd6' } }));
    expect(uploaded).toEqual(['model/obj']);
    expect(screen.getByTestId('import-progress')).toHaveTextContent('grid.obj: 200 triangles added as a mesh.');
    expect((store().scene.objects[index] as { position: number[] }).position[1]).toBe(0); // a flat grid lies on the floor
    expect(screen.queryByRole('alert')).toBeNull();
    expect(store().selection).toEqual({ kind: 'object', index });
    expect(store().past).toHaveLength(1);
    expect(screen.getByRole('heading', { name: 'Mesh "grid"' })).toBeInTheDocument();
    expect(screen.getByTestId('mesh-source')).toHaveTextContent(`uploaded OBJ ${id.slice(0, 15)}…, 200 triangles`);
    expect(within(screen.getByTestId('side-view')).getByTestId(`object-${index}`)).toHaveAttribute('data-selected', 'true');
    await user.click(screen.getByRole('button', { name: 'Undo' }));
    expect(store().scene).toEqual(STARTER_SCENE);
  });

  it('loads an example’s mesh file from the server once, and explains one it does not have', async () => {
    const user = userEvent.setup();
    const meshScene = {
      name: 'mesh',
      objects: [
        { type: 'mesh', file: 'meshes/torus-knot.obj', scale: 0.5 },
        { type: 'mesh', file: 'meshes/missing.obj' },
      ],
    };
    const fetchFn = mockServer({
      'GET /api/scenes/mesh': () => Response.json(meshScene),
      'GET /api/meshes?file=meshes%2Ftorus-knot.obj': () => new Response(gridObj(40, 1, 60), { headers: { 'Content-Type': 'text/plain' } }),
      'GET /api/meshes?file=meshes%2Fmissing.obj': () =>
        Response.json({ status: 404, title: 'Not Found', detail: "no mesh 'meshes/missing.obj' ships with this server" }, { status: 404, headers: { 'Content-Type': 'application/problem+json' } }),
    });
    await renderApp(fetchFn);
    act(() => store().loadScene(meshScene as never));
    const outline = screen.getByRole('navigation', { name: 'Scene contents' });
    expect(await within(outline).findByRole('button', { name: /Mesh 1 \(4,800 triangles\)/ })).toBeInTheDocument();
    await user.click(await within(outline).findByRole('button', { name: /Mesh 2 \(OBJ error\)/ }));
    expect(screen.getByRole('alert')).toHaveTextContent("Cannot read the OBJ: meshes/missing.obj: Not Found: no mesh 'meshes/missing.obj' ships with this server");
    act(() => store().moveObject(0, [1, 2, 3]));
    expect(fetchFn.mock.calls.filter(([url]) => url.startsWith('/api/meshes'))).toHaveLength(2);
  });

  it('takes an image dropped on the stage as the selected object’s texture, and says when nothing is selected', async () => {
    const png = new File([new Uint8Array([137, 80, 78, 71])], 'wood.png', { type: 'image/png' });
    const id = await assetIdOf(png);
    const fetchFn = mockServer({ [`HEAD /api/assets/${id}`]: () => new Response(null, { status: 200 }) });
    await renderApp(fetchFn);
    const drop = () => fireEvent.drop(screen.getByTestId('stage-drop'), { dataTransfer: { files: [png], types: ['Files'] } });
    act(() => store().select(null));
    drop();
    expect(await screen.findByRole('alert')).toHaveTextContent('Cannot use wood.png as a texture: select the object whose material it should cover first');
    act(() => store().select({ kind: 'object', index: 0 }));
    drop();
    await waitFor(() => expect(store().scene.objects[0].material?.texture).toEqual({ type: 'image', asset: id, scale: [1, 1] }));
    // the server had the bytes: nothing was uploaded
    expect(fetchFn.mock.calls.filter(([url, init]) => url === '/api/assets' && init?.method === 'POST')).toHaveLength(0);
    expect(store().past).toHaveLength(1);
  });
});
