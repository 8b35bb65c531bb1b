import { act, render, screen, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { fakeSockets } from '../test/liveFakes';
import type { Scene } from '../model/types';
import { recordingContext } from '../test/renderFakes';
import { useSceneStore } from '../store/sceneStore';
import { Preview3D } from './Preview3D';
import { ORBIT_SPEEDS } from './previewEngine';

const store = () => useSceneStore.getState();

/** The ray-traced view with a fake server: sockets recorded, frames "decoded" at once. */
function renderRayTraced(shown = true) {
  vi.useFakeTimers({ toFake: ['requestAnimationFrame', 'cancelAnimationFrame'] });
  vi.stubGlobal('createImageBitmap', async () => ({ close: () => {} }));
  vi.spyOn(HTMLCanvasElement.prototype, 'getContext').mockReturnValue(recordingContext().context as never);
  const sockets = fakeSockets();
  const onFieldErrors = vi.fn();
  const utils = render(<Preview3D shown={shown} onFieldErrors={onFieldErrors} socketFactory={sockets.factory} />);
  return { ...utils, sockets, onFieldErrors };
}

const nextFrame = () => act(async () => void vi.advanceTimersToNextFrame());

describe('Preview3D', () => {
  afterEach(() => {
    vi.useRealTimers();
    vi.unstubAllGlobals();
  });

  it('explains itself when WebGL is missing, and toggles between camera and orbit view', async () => {
    const user = userEvent.setup();
    render(<Preview3D />);
    expect(screen.getByRole('note')).toHaveTextContent('needs WebGL');
    const viewport = screen.getByTestId('preview-3d');
    expect(viewport).toHaveAttribute('data-mode', 'camera');
    expect(screen.getByRole('button', { name: 'Camera view' })).toHaveAttribute('aria-pressed', 'true');
    await user.click(screen.getByRole('button', { name: 'Orbit view' }));
    expect(viewport).toHaveAttribute('data-mode', 'orbit');
    expect(screen.getByRole('button', { name: 'Orbit view' })).toHaveAttribute('aria-pressed', 'true');
  });

  it('shows which handles W, E, R chose, and chooses them by click too', async () => {
    const user = userEvent.setup();
    render(<Preview3D />);
    const group = screen.getByRole('group', { name: '3D handles' });
    expect(within(group).getByRole('button', { name: 'Move' })).toHaveAttribute('aria-pressed', 'true');
    act(() => store().setGizmo('rotate'));
    expect(within(group).getByRole('button', { name: 'Rotate' })).toHaveAttribute('aria-pressed', 'true');
    await user.click(within(group).getByRole('button', { name: 'Scale' }));
    expect(store().gizmo).toBe('scale');
  });

  it('offers Reset view in the orbit view only, and orbits slower than OrbitControls by default', async () => {
    const user = userEvent.setup();
    render(<Preview3D />);
    expect(screen.queryByRole('button', { name: 'Reset view' })).toBeNull();
    await user.click(screen.getByRole('button', { name: 'Orbit view' }));
    expect(screen.getByRole('button', { name: 'Reset view' })).toBeInTheDocument();
    for (const speed of Object.values(ORBIT_SPEEDS)) expect(speed).toBeLessThan(1);
  });

  it('opens the live connection only while the Ray traced view is shown', () => {
    const { sockets, rerender, onFieldErrors } = renderRayTraced();
    expect(sockets.opened).toHaveLength(0);
    act(() => screen.getByRole('button', { name: 'Ray traced' }).click());
    expect(screen.getByRole('button', { name: 'Ray traced' })).toHaveAttribute('aria-pressed', 'true');
    expect(screen.getByTestId('ray-traced-view')).toBeInTheDocument();
    // the three.js view stays, as the handles' transparent layer over the live image
    expect(screen.getByTestId('preview-3d')).toHaveAttribute('data-mode', 'raytraced');
    expect(screen.getByTestId('preview-3d')).toHaveClass('is-overlay');
    expect(screen.getByRole('group', { name: '3D handles' })).toBeInTheDocument();
    expect(screen.queryByRole('note')).toBeNull(); // no WebGL here: nothing to say over the image
    expect(sockets.opened).toHaveLength(1);

    rerender(<Preview3D shown={false} onFieldErrors={onFieldErrors} socketFactory={sockets.factory} />); // the JSON tab
    expect(sockets.opened[0].closedBy).not.toBeNull();
    rerender(<Preview3D shown onFieldErrors={onFieldErrors} socketFactory={sockets.factory} />);
    expect(sockets.opened).toHaveLength(2);
    act(() => screen.getByRole('button', { name: 'Camera view' }).click());
    expect(sockets.opened[1].closedBy).not.toBeNull();
    expect(screen.queryByTestId('ray-traced-view')).toBeNull();
    expect(screen.getByTestId('preview-3d')).toBeVisible();
  });

  it("sends a drag's transient position at the view's size, draws the frames and says which pass it shows", async () => {
    const { sockets } = renderRayTraced();
    act(() => screen.getByRole('button', { name: 'Ray traced' }).click());
    const socket = sockets.last();
    act(() => socket.open());
    await nextFrame();
    const first = socket.revisions()[0];
    expect(first.scene).toEqual(store().scene);
    // letterboxed to the still life's 800x600 in the panel (480x320 until laid out)
    expect([first.width, first.height]).toEqual([427, 320]);

    act(() => store().dragTo({ kind: 'object', index: 0 }, [2, 0.5, 1]));
    await nextFrame();
    const dragged = socket.revisions()[1];
    expect(dragged.revision).toBe(2);
    expect((dragged.scene as Scene).objects[0]).toMatchObject({ center: [2, 0.5, 1] });
    expect(store().scene.objects[0]).not.toMatchObject({ center: [2, 0.5, 1] }); // not committed

    act(() => socket.frame({ revision: 2, pass: 1, width: 54, height: 40, millis: 12 }));
    const view = screen.getByTestId('ray-traced-view');
    expect(await within(view).findByText('pass 1 · 1 spp · 54x40 · 12 ms')).toBeInTheDocument();
    expect(within(view).getByRole('img')).toHaveAttribute('data-revision', '2');
  });

  it('shows a refused scene as the render panel does, field errors included', async () => {
    const { sockets, onFieldErrors } = renderRayTraced();
    act(() => screen.getByRole('button', { name: 'Ray traced' }).click());
    act(() => sockets.last().open());
    await nextFrame();
    act(() =>
      sockets.last().receive({
        revision: 1,
        problem: { title: 'Invalid scene', status: 400, errors: [{ field: 'camera.up', message: 'must not be parallel to the view direction' }] },
      }),
    );
    const summary = within(screen.getByTestId('ray-traced-view')).getByTestId('error-summary');
    expect(summary).toHaveTextContent('Invalid scene: 1 problem');
    expect(summary).toHaveTextContent('Camera › Up: must not be parallel to the view direction');
    expect(onFieldErrors).toHaveBeenLastCalledWith({ 'camera.up': 'must not be parallel to the view direction' });
  });
});
