import { render, screen, waitFor } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import type { FetchFn } from '../api/client';
import type { Scene } from '../model/types';
import { RenderArea } from './RenderArea';

const SCENE: Scene = { name: 'tiny', objects: [{ type: 'sphere' }] };

describe('RenderArea (simple render path)', () => {
  beforeEach(() => {
    vi.spyOn(URL, 'createObjectURL').mockImplementation(() => 'blob:test/1');
    vi.spyOn(URL, 'revokeObjectURL').mockImplementation(() => {});
  });

  it('posts the scene and shows the image with its statistics', async () => {
    const user = userEvent.setup();
    const fetchFn = vi.fn<FetchFn>(async () =>
      new Response(new Uint8Array([1]), { headers: { 'Content-Type': 'image/png', 'Content-Disposition': 'attachment; filename="tiny.png"', 'X-Render-Millis': '850' } }),
    );
    const onFieldErrors = vi.fn();
    render(<RenderArea scene={SCENE} onFieldErrors={onFieldErrors} fetchFn={fetchFn} />);
    await user.click(screen.getByRole('button', { name: 'Render' }));
    expect(await screen.findByRole('img', { name: 'Rendered scene' })).toHaveAttribute('src', 'blob:test/1');
    expect(screen.getByText('850 ms')).toBeInTheDocument();
    expect(fetchFn.mock.calls[0][1]?.body).toBe(JSON.stringify(SCENE));
    expect(onFieldErrors).toHaveBeenLastCalledWith({});
  });

  it('reports field errors of a 400 problem and lists them', async () => {
    const user = userEvent.setup();
    const fetchFn = vi.fn<FetchFn>(async () =>
      new Response(JSON.stringify({ title: 'Invalid scene', status: 400, errors: [{ field: 'objects[0].radius', message: 'must be greater than 0' }] }), {
        status: 400,
        headers: { 'Content-Type': 'application/problem+json' },
      }),
    );
    const onFieldErrors = vi.fn();
    render(<RenderArea scene={SCENE} onFieldErrors={onFieldErrors} fetchFn={fetchFn} />);
    await user.click(screen.getByRole('button', { name: 'Render' }));
    await waitFor(() => expect(onFieldErrors).toHaveBeenLastCalledWith({ 'objects[0].radius': 'must be greater than 0' }));
    expect(screen.getByRole('alert')).toHaveTextContent('objects[0].radius — must be greater than 0');
  });
});
