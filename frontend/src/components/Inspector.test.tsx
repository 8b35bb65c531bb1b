import { act, fireEvent, render, screen, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { describe, expect, it } from 'vitest';
import type { Scene } from '../model/types';
import { resetSceneStore, useSceneStore } from '../store/sceneStore';
import { FieldErrorsProvider } from './fieldErrors';
import { Inspector } from './Inspector';

const store = () => useSceneStore.getState();

const SCENE: Scene = {
  name: 'inspect',
  lights: [{ type: 'point', position: [1, 2, 3] }],
  objects: [
    { type: 'sphere', center: [1, 1, 2], radius: 0.5, material: { type: 'plastic', color: '#cc3333' } },
    { type: 'box', center: [0, 0.5, 0] },
    { type: 'plane' },
  ],
};

function field(path: string): HTMLElement {
  const el = document.querySelector(`[data-field="${path}"]`);
  if (!el) throw new Error(`no input for ${path}`);
  return el as HTMLElement;
}

describe('Inspector', () => {
  it('sets the image size from a preset, and keeps its aspect with the lock (one undo step each)', async () => {
    const user = userEvent.setup();
    render(<Inspector />);
    await user.selectOptions(screen.getByLabelText('Size preset'), '1280 × 720 (HD)');
    expect(store().scene.image).toMatchObject({ width: 1280, height: 720 });
    expect(store().past).toHaveLength(1);
    await user.click(screen.getByLabelText(/Lock aspect ratio/));
    const width = screen.getByLabelText('Width (px)');
    await user.clear(width);
    await user.type(width, '1920{Enter}');
    expect(store().scene.image).toMatchObject({ width: 1920, height: 1080 });
    expect(store().past).toHaveLength(2);
    expect(screen.getByLabelText('Size preset')).toHaveValue('2');
  });

  it('sizes a narrow vector input by the length of its text, so 100000.004 shows whole', () => {
    resetSceneStore({ objects: [{ type: 'sphere', center: [100000.004, 1, 2] }] });
    store().select({ kind: 'object', index: 0 });
    render(<Inspector />);
    const x = screen.getByLabelText('Center x') as HTMLInputElement;
    expect(x.value).toBe('100000.004');
    expect(x.style.getPropertyValue('--chars')).toBe('10');
    expect((screen.getByLabelText('Center y') as HTMLInputElement).style.getPropertyValue('--chars')).toBe('4');
  });

  it('edits the selected object: typing commits once on Enter, one undo step', async () => {
    const user = userEvent.setup();
    resetSceneStore(SCENE);
    store().select({ kind: 'object', index: 0 });
    render(<Inspector />);
    const x = screen.getByLabelText('Center x');
    expect(x).toHaveAttribute('data-field', 'objects[0].center[0]');
    expect(x).toHaveValue(1);
    await user.clear(x);
    await user.type(x, '2.75{Enter}');
    expect(store().scene.objects[0]).toMatchObject({ center: [2.75, 1, 2] });
    expect(store().past).toHaveLength(1);

    const radius = screen.getByLabelText('Radius');
    await user.clear(radius);
    await user.type(radius, '1.5');
    await user.tab();
    expect(store().scene.objects[0]).toMatchObject({ radius: 1.5 });
    expect(store().past).toHaveLength(2);
  });

  it('refuses a value out of range: it stays with its reason beside the field until Escape reverts it', async () => {
    const user = userEvent.setup();
    resetSceneStore(SCENE);
    store().select({ kind: 'object', index: 0 });
    render(<Inspector />);
    const radius = screen.getByLabelText('Radius');
    await user.clear(radius);
    await user.type(radius, '-1');
    await user.keyboard('{Enter}');
    expect(store().past).toHaveLength(0);
    expect(radius).toHaveValue(-1);
    expect(radius).toHaveAttribute('aria-invalid', 'true');
    expect(radius).toHaveAccessibleDescription('must be greater than 0');
    await user.tab();
    expect(radius).toHaveAccessibleDescription('must be greater than 0');
    await user.click(radius);
    await user.keyboard('{Escape}');
    expect(radius).toHaveValue(0.5);
    expect(radius).not.toHaveAttribute('aria-invalid');
    expect(screen.queryByText('must be greater than 0')).toBeNull();
  });

  it('renames an object in the inspector and in the list; deleting another keeps its label', async () => {
    const user = userEvent.setup();
    resetSceneStore({ objects: [{ type: 'box' }, { type: 'sphere' }] });
    store().select({ kind: 'object', index: 1 });
    render(<Inspector />);
    expect(screen.getByRole('heading', { name: 'Sphere 2' })).toBeInTheDocument();
    await user.type(within(screen.getByTestId('inspector-object')).getByLabelText('Name'), 'ball{Enter}');
    expect(store().scene.objects[1]).toEqual({ type: 'sphere', name: 'ball' });
    expect(screen.getByRole('heading', { name: 'Sphere "ball"' })).toBeInTheDocument();
    await user.dblClick(screen.getByRole('button', { name: /^Box 1/ }));
    await user.type(screen.getByLabelText('New name for Box 1'), 'crate{Enter}');
    expect(store().scene.objects[0]).toEqual({ type: 'box', name: 'crate' });
    act(() => store().select({ kind: 'object', index: 1 }));
    await user.clear(within(screen.getByTestId('inspector-object')).getByLabelText('Name'));
    await user.keyboard('{Enter}');
    expect(store().scene.objects[1]).toEqual({ type: 'sphere' });
    act(() => {
      store().select({ kind: 'object', index: 0 });
      store().deleteSelected();
    });
    expect(screen.getByRole('button', { name: /^Sphere 2/ })).toBeInTheDocument();
  });

  it('refuses a width over the limit and says why, until it is fixed', async () => {
    const user = userEvent.setup();
    resetSceneStore(SCENE);
    render(<Inspector />);
    const width = screen.getByLabelText('Width (px)');
    await user.clear(width);
    await user.type(width, '8000{Enter}');
    expect(width).toHaveAccessibleDescription('must be at most 4096');
    await user.clear(width);
    await user.type(width, '1024{Enter}');
    expect(store().scene.image?.width).toBe(1024);
    expect(width).not.toHaveAttribute('aria-invalid');
  });

  it('takes #f00 and ff0000 as colours and explains why "red" is refused', async () => {
    const user = userEvent.setup();
    resetSceneStore(SCENE);
    render(<Inspector />);
    const hex = screen.getByLabelText('Background hex');
    await user.clear(hex);
    await user.type(hex, '#f00{Enter}');
    expect(store().scene.background).toBe('#ff0000');
    await user.clear(hex);
    await user.type(hex, '00ff00{Enter}');
    expect(store().scene.background).toBe('#00ff00');
    await user.clear(hex);
    await user.type(hex, 'red{Enter}');
    expect(store().scene.background).toBe('#00ff00');
    expect(hex).toHaveValue('red');
    expect(hex).toHaveAttribute('aria-invalid', 'true');
    expect(hex).toHaveAccessibleDescription('must be a hex colour such as #ff8800 or #f80');
  });

  it('changes the material kind and shows only that kind’s overrides', async () => {
    const user = userEvent.setup();
    resetSceneStore(SCENE);
    store().select({ kind: 'object', index: 0 });
    render(<Inspector />);
    const type = screen.getByLabelText('Material type');
    expect(type).toHaveAttribute('data-field', 'objects[0].material.type');
    expect(screen.getByLabelText('Shininess')).toHaveValue(60);
    await user.selectOptions(type, 'glass');
    expect(store().scene.objects[0].material).toEqual({ type: 'glass' }); // a red plastic's colour is no glass tint
    expect(screen.getByLabelText('Index of refraction')).toHaveValue(1.5);
    expect(screen.queryByLabelText('Diffuse')).toBeNull();
    await user.clear(screen.getByLabelText('Color hex'));
    await user.type(screen.getByLabelText('Color hex'), '#00ff00{Enter}');
    expect(store().scene.objects[0].material).toEqual({ type: 'glass', color: '#00ff00' });
    fireEvent.change(screen.getByLabelText('Color'), { target: { value: '#0000ff' } });
    expect(store().scene.objects[0].material?.color).toBe('#0000ff');
  });

  it('shows box, plane, light, camera and scene fields with their JSON paths', async () => {
    const user = userEvent.setup();
    resetSceneStore(SCENE);
    store().select({ kind: 'object', index: 1 });
    const { rerender } = render(<Inspector />);
    expect(screen.getByLabelText('Rotation y')).toHaveAttribute('data-field', 'objects[1].rotation[1]');
    expect(screen.getByLabelText('Size z')).toHaveValue(1);
    store().select({ kind: 'object', index: 2 });
    rerender(<Inspector />);
    expect(screen.getByLabelText('Normal y')).toHaveAttribute('data-field', 'objects[2].normal[1]');
    store().select({ kind: 'light', index: 0 });
    rerender(<Inspector />);
    expect(screen.getByLabelText('Light position z')).toHaveValue(3);
    await user.click(screen.getByLabelText('Falls off with distance (1/d²)'));
    expect(store().scene.lights?.[0].falloff).toBe(true);
    for (const path of ['camera.position[0]', 'camera.lookAt[2]', 'camera.up[1]', 'camera.fov', 'name', 'background', 'ambient', 'image.width', 'image.height', 'image.format', 'render.sampler', 'render.samples', 'render.maxDepth', 'render.seed', 'render.adaptive']) {
      expect(field(path)).toBeInTheDocument();
    }
    const width = screen.getByLabelText('Width (px)');
    await user.clear(width);
    await user.type(width, '320{Enter}');
    expect(store().scene.image).toMatchObject({ width: 320 });
    await user.selectOptions(screen.getByLabelText('Sampler'), 'regular');
    expect(store().scene.render).toMatchObject({ sampler: 'regular', adaptive: 0 });
    await user.selectOptions(screen.getByLabelText('Sampler'), 'sobol');
    expect(store().scene.render?.sampler).toBe('sobol');
    const adaptive = screen.getByLabelText('Adaptive threshold');
    await user.clear(adaptive);
    await user.type(adaptive, '0.1{Enter}');
    expect(store().scene.render).toMatchObject({ sampler: 'sobol', adaptive: 0.1 });
  });

  it('selects from the outline', async () => {
    const user = userEvent.setup();
    resetSceneStore(SCENE);
    render(<Inspector />);
    const outline = screen.getByRole('navigation', { name: 'Scene contents' });
    await user.click(within(outline).getByRole('button', { name: /Box 2/ }));
    expect(store().selection).toEqual({ kind: 'object', index: 1 });
    expect(within(outline).getByRole('button', { name: /Box 2/ })).toHaveAttribute('aria-pressed', 'true');
    // a second click (or the first half of a double-click to rename) keeps it selected
    await user.click(within(outline).getByRole('button', { name: /Box 2/ }));
    expect(store().selection).toEqual({ kind: 'object', index: 1 });
  });

  it('shows a server field error next to the input whose path it names', () => {
    resetSceneStore(SCENE);
    store().select({ kind: 'object', index: 0 });
    render(
      <FieldErrorsProvider errors={{ 'objects[0].radius': 'must be greater than 0', 'camera.up': 'must not be a zero-length vector', 'image.width': 'must be at most 4096' }}>
        <Inspector />
      </FieldErrorsProvider>,
    );
    const radius = screen.getByLabelText('Radius');
    const message = radius.parentElement!.querySelector('.field-error');
    expect(message).toHaveTextContent('must be greater than 0');
    expect(radius).toHaveAttribute('aria-invalid', 'true');
    expect(radius).toHaveAccessibleDescription('must be greater than 0');
    expect(document.querySelector('[data-field-error="camera.up"]')).toHaveTextContent('must not be a zero-length vector');
    expect(screen.getByLabelText('Width (px)')).toHaveAccessibleDescription('must be at most 4096');
    expect(document.querySelectorAll('.field-error')).toHaveLength(3);
  });
});
