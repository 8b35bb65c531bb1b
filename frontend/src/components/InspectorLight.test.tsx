import { render, screen, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { describe, expect, it, vi } from 'vitest';
import type { FetchFn } from '../api/client';
import { useSceneErrors } from '../hooks/useSceneErrors';
import type { Scene } from '../model/types';
import { resetSceneStore, useSceneStore } from '../store/sceneStore';
import { FieldErrorsProvider } from './fieldErrors';
import { Inspector } from './Inspector';
import { ProblemList } from './ProblemList';
import { Toolbar } from './Toolbar';

const store = () => useSceneStore.getState();

const SCENE: Scene = {
  objects: [],
  lights: [
    { type: 'point', position: [1, 2, 3] },
    { type: 'area', position: [0, 3, 0], size: [2, 1], lookAt: [0, 0, 0], color: '#ffeedd', intensity: 2, falloff: false, twoSided: false },
  ],
};

/** The inspector with the editor's own checks of the scene at its fields, as the app shows it. */
function CheckedInspector() {
  return (
    <FieldErrorsProvider errors={useSceneErrors()}>
      <ProblemList />
      <Inspector />
    </FieldErrorsProvider>
  );
}

describe('the light inspector', () => {
  it('gives a point light a radius: one undo step, a negative one refused with its reason', async () => {
    const user = userEvent.setup();
    resetSceneStore(SCENE);
    store().select({ kind: 'light', index: 0 });
    render(<CheckedInspector />);
    const radius = screen.getByLabelText('Radius');
    expect(radius).toHaveAttribute('data-field', 'lights[0].radius');
    expect(radius).toHaveValue(0);
    await user.clear(radius);
    await user.type(radius, '0.25{Enter}');
    expect(store().scene.lights![0]).toEqual({ type: 'point', position: [1, 2, 3], radius: 0.25 });
    expect(store().past).toHaveLength(1);
    await user.clear(radius);
    await user.type(radius, '-1{Enter}');
    expect(store().scene.lights![0]).toMatchObject({ radius: 0.25 });
    expect(store().past).toHaveLength(1);
    expect(radius).toHaveAttribute('aria-invalid', 'true');
    expect(radius).toHaveAccessibleDescription('must be at least 0');
  });

  it('flags a negative radius that came with the scene at its field and in the problem list', () => {
    resetSceneStore({ objects: [], lights: [{ type: 'point', radius: -2 }] });
    store().select({ kind: 'light', index: 0 });
    render(<CheckedInspector />);
    expect(screen.getByLabelText('Radius')).toHaveAttribute('aria-invalid', 'true');
    expect(screen.getByLabelText('Radius')).toHaveAccessibleDescription('must be at least 0');
    expect(screen.getByTestId('problem-list')).toHaveTextContent('Light 1 › Radius: must be greater than or equal to 0');
  });

  it('edits an area light: position, size, aim, colour, intensity, fall-off and two sides, each one undo step', async () => {
    const user = userEvent.setup();
    resetSceneStore(SCENE);
    store().select({ kind: 'light', index: 1 });
    render(<CheckedInspector />);
    const section = screen.getByTestId('inspector-light');
    expect(within(section).getByRole('heading')).toHaveTextContent('Area light 2');
    expect(screen.queryByLabelText('Radius')).toBeNull();
    expect(within(section).getByLabelText('Name')).toHaveAttribute('data-field', 'lights[1].name'); // named as any light
    for (const [label, path, value] of [
      ['Light position y', 'lights[1].position[1]', 3],
      ['Size w', 'lights[1].size[0]', 2],
      ['Size h', 'lights[1].size[1]', 1],
      ['Aim (look at) x', 'lights[1].lookAt[0]', 0],
      ['Intensity', 'lights[1].intensity', 2],
    ] as const) {
      expect(screen.getByLabelText(label)).toHaveAttribute('data-field', path);
      expect(screen.getByLabelText(label)).toHaveValue(value);
    }
    const height = screen.getByLabelText('Size h');
    await user.clear(height);
    await user.type(height, '0.5{Enter}');
    expect(store().scene.lights![1]).toMatchObject({ size: [2, 0.5] });
    const aimZ = screen.getByLabelText('Aim (look at) z');
    await user.clear(aimZ);
    await user.type(aimZ, '1{Enter}');
    expect(store().scene.lights![1]).toMatchObject({ lookAt: [0, 0, 1], position: [0, 3, 0] });
    await user.click(screen.getByLabelText('Two-sided'));
    await user.click(screen.getByLabelText('Falls off with distance (1/d²)'));
    expect(store().scene.lights![1]).toMatchObject({ twoSided: true, falloff: true });
    expect(store().past).toHaveLength(4);
  });

  it('refuses a width of 0 as it is typed, and an aim on the light’s own position at the field', async () => {
    const user = userEvent.setup();
    resetSceneStore(SCENE);
    store().select({ kind: 'lightAim', index: 1 });
    render(<CheckedInspector />);
    const outline = screen.getByRole('navigation', { name: 'Scene contents' });
    expect(within(outline).getByRole('button', { name: 'Area light 2' })).toHaveAttribute('aria-pressed', 'true');
    await user.click(within(outline).getByRole('button', { name: 'Area light 2' })); // picks the light itself
    expect(store().selection).toEqual({ kind: 'light', index: 1 });
    store().select({ kind: 'lightAim', index: 1 });
    const width = screen.getByLabelText('Size w');
    await user.clear(width);
    await user.type(width, '0{Enter}');
    expect(store().scene.lights![1]).toMatchObject({ size: [2, 1] });
    expect(width).toHaveAccessibleDescription('must be greater than 0');
    const aimY = screen.getByLabelText('Aim (look at) y');
    await user.clear(aimY);
    await user.type(aimY, '3{Enter}');
    expect(store().scene.lights![1]).toMatchObject({ lookAt: [0, 3, 0] });
    expect(document.querySelector('[data-field-error="lights[1].lookAt"]')).toHaveTextContent('must differ from Area light 2 › Position');
    expect(screen.getByTestId('problem-list')).toHaveTextContent('Area light 2 › Aim: must differ from Area light 2 › Position');
  });

  it('lists an area light to rename as any light, and adds one from the toolbar, selected', async () => {
    const user = userEvent.setup();
    resetSceneStore(SCENE);
    const fetchFn = vi.fn<FetchFn>(async () => Response.json([]));
    render(
      <>
        <Toolbar fetchFn={fetchFn} onMessage={() => {}} />
        <CheckedInspector />
      </>,
    );
    const outline = screen.getByRole('navigation', { name: 'Scene contents' });
    const area = within(outline).getByRole('button', { name: 'Area light 2' });
    expect(area.title).toMatch(/rename/);
    await user.dblClick(area);
    expect(screen.getByLabelText(/New name for/)).toBeInTheDocument();
    await user.keyboard('{Escape}');
    await user.click(screen.getByRole('button', { name: 'Add area light' }));
    expect(store().scene.lights).toHaveLength(3);
    expect(store().scene.lights![2]).toMatchObject({ type: 'area', position: [2, 3, 1], lookAt: [2, 0, 1] }); // the camera is at +z
    expect(store().selection).toEqual({ kind: 'light', index: 2 });
    expect(within(screen.getByTestId('inspector-light')).getByRole('heading')).toHaveTextContent('Area light 3');
  });
});
