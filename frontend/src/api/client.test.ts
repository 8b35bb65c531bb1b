import { describe, expect, it, vi } from 'vitest';
import {
  ApiError,
  fetchMeshFile,
  fetchScene,
  fetchSceneList,
  filenameFromDisposition,
  renderScene,
  type FetchFn,
} from './client';

const PNG_BYTES = new Uint8Array([0x89, 0x50, 0x4e, 0x47, 0x0d, 0x0a, 0x1a, 0x0a]);

/** A fetch that answers every request with the given response. */
function answering(response: Response) {
  return vi.fn<FetchFn>(async () => response);
}

async function rejectionOf(promise: Promise<unknown>): Promise<ApiError> {
  const error = await promise.then(
    () => {
      throw new Error('expected the promise to reject');
    },
    (e: unknown) => e,
  );
  expect(error).toBeInstanceOf(ApiError);
  return error as ApiError;
}

describe('renderScene', () => {
  it('posts the text unchanged as application/json', async () => {
    const fetchFn = answering(new Response(PNG_BYTES, { headers: { 'Content-Type': 'image/png' } }));
    const text = '{ "objects": [] }';
    await renderScene(text, fetchFn);
    expect(fetchFn).toHaveBeenCalledTimes(1);
    const [url, init] = fetchFn.mock.calls[0];
    expect(url).toBe('/api/render');
    expect(init?.method).toBe('POST');
    expect(new Headers(init?.headers).get('Content-Type')).toBe('application/json');
    expect(init?.body).toBe(text);
  });

  it('reads the image, its file name and the render statistics', async () => {
    const fetchFn = answering(
      new Response(PNG_BYTES, {
        headers: {
          'Content-Type': 'image/png',
          'Content-Disposition': 'attachment; filename="six-materials.png"',
          'X-Render-Millis': '1234',
          'X-Rays-Per-Second': '5600000',
        },
      }),
    );
    const output = await renderScene('{}', fetchFn);
    expect(output.filename).toBe('six-materials.png');
    expect(output.contentType).toBe('image/png');
    expect(output.renderMillis).toBe(1234);
    expect(output.raysPerSecond).toBe(5_600_000);
    expect(new Uint8Array(await output.image.arrayBuffer())).toEqual(PNG_BYTES);
  });

  it('falls back to render.png without Content-Disposition and leaves missing stats undefined', async () => {
    const fetchFn = answering(new Response(PNG_BYTES, { headers: { 'Content-Type': 'image/png' } }));
    const output = await renderScene('{}', fetchFn);
    expect(output.filename).toBe('render.png');
    expect(output.renderMillis).toBeUndefined();
    expect(output.raysPerSecond).toBeUndefined();
  });

  it('turns a problem+json answer into an ApiError naming each field', async () => {
    const problem = {
      type: 'about:blank',
      title: 'Invalid scene',
      status: 400,
      detail: '2 fields are invalid',
      errors: [
        { field: 'objects[2].radius', message: 'must be greater than 0' },
        { field: 'image.width', message: 'must be at most 4096' },
      ],
    };
    const fetchFn = answering(
      new Response(JSON.stringify(problem), {
        status: 400,
        headers: { 'Content-Type': 'application/problem+json' },
      }),
    );
    const error = await rejectionOf(renderScene('{}', fetchFn));
    expect(error.status).toBe(400);
    expect(error.title).toBe('Invalid scene');
    expect(error.detail).toBe('2 fields are invalid');
    expect(error.errors).toEqual(problem.errors);
  });

  it('turns a non-problem error into an ApiError from the status line', async () => {
    const fetchFn = answering(
      new Response('<html>busy</html>', {
        status: 503,
        statusText: 'Service Unavailable',
        headers: { 'Content-Type': 'text/html', 'Retry-After': '5' },
      }),
    );
    const error = await rejectionOf(renderScene('{}', fetchFn));
    expect(error.status).toBe(503);
    expect(error.title).toBe('Service Unavailable');
    expect(error.detail).toContain('Try again in 5 s');
    expect(error.errors).toEqual([]);
  });

  it('explains a 413 without a status text', async () => {
    const fetchFn = answering(new Response('', { status: 413 }));
    const error = await rejectionOf(renderScene('{}', fetchFn));
    expect(error.title).toBe('Payload Too Large');
    expect(error.detail).toMatch(/larger than the server accepts/);
  });

  it('reports a network failure as status 0', async () => {
    const fetchFn = vi.fn<FetchFn>(async () => {
      throw new TypeError('Failed to fetch');
    });
    const error = await rejectionOf(renderScene('{}', fetchFn));
    expect(error.status).toBe(0);
    expect(error.title).toBe('Cannot reach the server');
    expect(error.detail).toBe('Failed to fetch');
  });
});

describe('filenameFromDisposition', () => {
  it('reads quoted, bare and RFC 6266 extended names and strips paths', () => {
    expect(filenameFromDisposition('attachment; filename="a b.png"')).toBe('a b.png');
    expect(filenameFromDisposition('attachment; filename=plain.jpg')).toBe('plain.jpg');
    expect(filenameFromDisposition(`attachment; filename="x.png"; filename*=UTF-8''caf%C3%A9.png`)).toBe('café.png');
    expect(filenameFromDisposition('attachment; filename="../../etc/passwd"')).toBe('passwd');
  });

  it('falls back by media type when the header has no usable name', () => {
    expect(filenameFromDisposition(null)).toBe('render.png');
    expect(filenameFromDisposition('attachment')).toBe('render.png');
    expect(filenameFromDisposition('attachment; filename=""', 'image/jpeg')).toBe('render.jpg');
  });
});

describe('scene examples', () => {
  it('lists the examples by name', async () => {
    const fetchFn = answering(Response.json([{ name: 'six-materials' }, { name: 'three-spheres' }]));
    expect(await fetchSceneList(fetchFn)).toEqual([{ name: 'six-materials' }, { name: 'three-spheres' }]);
    expect(fetchFn.mock.calls[0][0]).toBe('/api/scenes');
  });

  it('loads one example by its encoded name and surfaces a 404 problem', async () => {
    const ok = answering(Response.json({ objects: [] }));
    expect(await fetchScene('a b', ok)).toEqual({ objects: [] });
    expect(ok.mock.calls[0][0]).toBe('/api/scenes/a%20b');

    const missing = answering(
      new Response(JSON.stringify({ title: 'Not Found', status: 404, detail: 'No scene nope' }), {
        status: 404,
        headers: { 'Content-Type': 'application/problem+json; charset=utf-8' },
      }),
    );
    const error = await rejectionOf(fetchScene('nope', missing));
    expect(error.title).toBe('Not Found');
    expect(error.detail).toBe('No scene nope');
  });
});

const OBJ = 'v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n';

describe('fetchMeshFile', () => {
  it('asks for the file by its encoded name and returns the OBJ text', async () => {
    const fetchFn = vi.fn<FetchFn>(async () => new Response(OBJ, { headers: { 'Content-Type': 'text/plain' } }));
    expect(await fetchMeshFile('meshes/torus knot.obj', fetchFn)).toBe(OBJ);
    expect(fetchFn).toHaveBeenCalledWith('/api/meshes?file=meshes%2Ftorus%20knot.obj', expect.objectContaining({ headers: expect.objectContaining({ Accept: expect.stringContaining('text/plain') }) }));
  });

  it('turns a problem body into an ApiError', async () => {
    const fetchFn = vi.fn<FetchFn>(async () =>
      Response.json({ status: 404, title: 'Not Found', detail: 'no such mesh' }, { status: 404, headers: { 'Content-Type': 'application/problem+json' } }),
    );
    const error = await rejectionOf(fetchMeshFile('x.obj', fetchFn));
    expect(error).toMatchObject({ status: 404, title: 'Not Found', detail: 'no such mesh' });
  });
});
