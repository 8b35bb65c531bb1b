import { act, cleanup, fireEvent, screen, within } from '@testing-library/react';
import { beforeEach, describe, expect, it, vi } from 'vitest';
import { useSceneStore } from '../store/sceneStore';
import { MemoryHistoryStorage } from '../test/renderFakes';
import { freshHistory, mockServer, SCENE, setup } from '../test/panelHarness';

const RED = { ...SCENE, objects: [{ type: 'sphere', material: { type: 'chalk', color: '#d03020' } }] };
const BLUE = { ...SCENE, objects: [{ type: 'sphere', material: { type: 'chalk', color: '#2040d0' } }] };

/** Renders RED, then BLUE (job1, job2), as a user who changed the colour between. */
async function twoRenders(history = freshHistory(), more = {}) {
  const panel = setup(mockServer({}, true), history, RED, more);
  await panel.renderToEnd('job1');
  panel.edit(BLUE);
  await panel.renderToEnd('job2');
  return panel;
}

/** Opens the History strip and returns its list of renders. */
async function openHistory(user: ReturnType<typeof setup>['user']) {
  await user.click(screen.getByRole('button', { name: /^History/ }));
  return within(screen.getByRole('region', { name: 'Render history' }));
}

describe('RenderPanel history', () => {
  beforeEach(() => {
    let next = 0;
    vi.spyOn(URL, 'createObjectURL').mockImplementation(() => `blob:test/${++next}`);
    vi.spyOn(URL, 'revokeObjectURL').mockImplementation(() => {});
  });

  it('lists each finished render with its scene, time, size and samples, newest first', async () => {
    const { user, history } = await twoRenders();
    expect(screen.getByRole('button', { name: 'History (2)' })).toHaveAttribute('aria-expanded', 'false');
    const strip = await openHistory(user);
    const renders = strip.getAllByRole('button').filter((b) => b.hasAttribute('aria-pressed'));
    // the visible text is the name (a screen reader says what a sighted user sees); the title says it all
    expect(renders.map((b) => b.textContent)).toEqual([
      expect.stringMatching(/^Render 2 still-life/),
      expect.stringMatching(/^Render 1 still-life/),
    ]);
    expect(renders.map((b) => b.getAttribute('title'))).toEqual([
      expect.stringMatching(/^Render 2: still-life · \d\d:\d\d:\d\d · 64 × 32 px · up to 16 spp · 1\.5 s$/),
      expect.stringMatching(/^Render 1: still-life · /),
    ]);
    // the newest is the one on the stage
    expect(renders[0]).toHaveAttribute('aria-pressed', 'true');
    expect(screen.getByTestId('render-stats')).toHaveTextContent(/Render 2 · \d\d:\d\d:\d\d · up to 16 spp/);
    expect(history.snapshot().entries.map((e) => e.record.scene)).toEqual([BLUE, RED]);
  });

  it('shows a render picked in the history on the stage, marked Out of date against the scene in the editor', async () => {
    const { user, history } = await twoRenders();
    const strip = await openHistory(user);
    await user.click(strip.getByRole('button', { name: /^Render 1 / }));
    const first = history.snapshot().entries[1];
    expect(screen.getByTestId('render-image')).toHaveAttribute('src', first.url);
    expect(screen.getByTestId('download-link')).toHaveAttribute('href', first.url);
    expect(screen.getByText('Out of date')).toBeVisible();
    expect(strip.getByRole('button', { name: /^Render 1 / })).toHaveAttribute('aria-pressed', 'true');
  });

  it('compares two renders over each other, fitted alike, with a slider moved by the keys and by dragging', async () => {
    const { user, history } = await twoRenders();
    const strip = await openHistory(user);
    await user.click(strip.getByRole('button', { name: 'Compare Render 1 with Render 2' }));
    const [second, first] = history.snapshot().entries;
    const left = screen.getByTestId('compare-image-left');
    const right = screen.getByTestId('compare-image-right');
    expect(left).toHaveAttribute('href', first.url);
    expect(right).toHaveAttribute('href', second.url);
    for (const a of ['x', 'y', 'width', 'height']) expect(left.getAttribute(a)).toBe(right.getAttribute(a));
    expect(screen.getByTestId('compare-left')).toHaveTextContent('Render 1');
    expect(screen.getByTestId('compare-right')).toHaveTextContent('Render 2');
    expect(screen.queryByText('Out of date')).toBeNull();

    const slider = screen.getByRole('slider', { name: 'Divider between the two renders' });
    expect(slider).toHaveAttribute('aria-valuenow', '50');
    slider.focus();
    await user.keyboard('{ArrowLeft}{ArrowLeft}');
    expect(slider).toHaveAttribute('aria-valuenow', '48');
    await user.keyboard('{Shift>}{ArrowRight}{/Shift}');
    expect(slider).toHaveAttribute('aria-valuenow', '58');
    await user.keyboard('{End}');
    expect(slider).toHaveAttribute('aria-valuenow', '100');
    // the right image shows right of the divider only
    const clip = document.getElementById(right.getAttribute('clip-path')!.slice(5, -1))!.querySelector('rect')!;
    expect(clip).toHaveAttribute('x', '64');
    expect(clip).toHaveAttribute('width', '0');

    // a drag anywhere on the frame: the frame is drawn 640 px wide from x = 100
    vi.spyOn(SVGElement.prototype, 'getBoundingClientRect').mockReturnValue({ left: 100, width: 640, top: 0, height: 320 } as DOMRect);
    const svg = slider.closest('svg')!;
    fireEvent.pointerDown(svg, { clientX: 260, pointerId: 1 });
    expect(slider).toHaveAttribute('aria-valuenow', '25');
    fireEvent.pointerMove(svg, { clientX: 420, pointerId: 1 });
    expect(slider).toHaveAttribute('aria-valuenow', '50');
    fireEvent.pointerUp(svg, { pointerId: 1 });
    fireEvent.pointerMove(svg, { clientX: 700, pointerId: 1 });
    expect(slider).toHaveAttribute('aria-valuenow', '50');

    await user.click(screen.getByRole('button', { name: 'End comparison' }));
    expect(screen.queryByRole('slider')).toBeNull();
    expect(screen.getByTestId('render-image')).toBeInTheDocument();
  });

  it('says how renders get into an empty history, and opens and closes with its button', async () => {
    const { user } = setup(mockServer(), freshHistory());
    const button = screen.getByRole('button', { name: 'History' });
    await user.click(button);
    expect(button).toHaveAttribute('aria-expanded', 'true');
    expect(screen.getByRole('region', { name: 'Render history' })).toHaveTextContent('No renders yet: each finished render appears here.');
    expect(button.getAttribute('aria-controls')).toBe(screen.getByRole('region', { name: 'Render history' }).id);
    await user.click(button);
    expect(screen.queryByRole('region', { name: 'Render history' })).toBeNull();
  });

  it('offers Compare only against another render shown', async () => {
    const { user } = await twoRenders();
    const strip = await openHistory(user);
    expect(strip.getByRole('button', { name: 'Compare Render 2' })).toBeDisabled();
    expect(strip.getByRole('button', { name: 'Compare Render 1 with Render 2' })).toBeEnabled();
  });

  it("restores a render's scene in the editor as one undo step, and shows that render, up to date", async () => {
    useSceneStore.getState().setScene(structuredClone(BLUE) as never);
    const before = useSceneStore.getState().past.length;
    const { user } = await twoRenders();
    const strip = await openHistory(user);
    expect(strip.getByRole('button', { name: 'Restore scene of Render 2' })).toBeDisabled();
    await user.click(strip.getByRole('button', { name: 'Restore scene of Render 1' }));
    expect(useSceneStore.getState().scene).toEqual(RED);
    expect(useSceneStore.getState().past).toHaveLength(before + 1);
    act(() => useSceneStore.getState().undo());
    expect(useSceneStore.getState().scene).toEqual(BLUE);
    expect(strip.getByRole('button', { name: /^Render 1 / })).toHaveAttribute('aria-pressed', 'true');
  });

  it('hands the scene to onRestoreScene when given one', async () => {
    const onRestoreScene = vi.fn();
    const { user } = await twoRenders(freshHistory(), { onRestoreScene });
    const strip = await openHistory(user);
    await user.click(strip.getByRole('button', { name: 'Restore scene of Render 1' }));
    expect(onRestoreScene).toHaveBeenCalledWith(RED);
  });

  it('shows the last render again after a reload, Out of date once the scene differs', async () => {
    const storage = new MemoryHistoryStorage();
    await twoRenders(freshHistory(storage));
    cleanup();

    // a reload: a new page, the same storage, the scene the editor saved
    const reloaded = freshHistory(storage);
    const page = setup(mockServer(), reloaded, BLUE);
    const image = await screen.findByTestId('render-image');
    expect(image).toHaveAttribute('src', reloaded.snapshot().entries[0].url);
    expect(screen.getByTestId('render-stats')).toHaveTextContent('Render 2');
    expect(screen.getByTestId('download-link')).toHaveTextContent('Download still-life.png');
    expect(screen.queryByText('Out of date')).toBeNull();
    expect(screen.getByRole('button', { name: 'History (2)' })).toBeInTheDocument();
    page.edit(RED);
    expect(screen.getByText('Out of date')).toBeVisible();
  });

  it("clears the stage's render for a new document (New, Open, an example), for good, but keeps the history", async () => {
    const storage = new MemoryHistoryStorage();
    const history = freshHistory(storage);
    await twoRenders(history);
    act(() => useSceneStore.getState().newScene());
    // the editor mounts a new panel for the new document
    cleanup();
    setup(mockServer(), history, BLUE);
    expect(screen.getByText(/Press Render to trace the scene/)).toBeInTheDocument();
    expect(screen.queryByTestId('render-image')).toBeNull();
    expect(screen.getByRole('button', { name: 'History (2)' })).toBeInTheDocument();

    // and a reload of the new document finds the history, not a render on the stage
    cleanup();
    const reloaded = freshHistory(storage);
    setup(mockServer(), reloaded, BLUE);
    await act(() => reloaded.whenLoaded());
    expect(screen.getByRole('button', { name: 'History (2)' })).toBeInTheDocument();
    expect(screen.queryByTestId('render-image')).toBeNull();
  });
});
