import { render, screen } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { ImportContext } from '../import/ImportContext';
import { meshCache } from '../hooks/useMeshes';
import { boxMesh } from '../model/obj';
import type { Scene } from '../model/types';
import { resetSceneStore, useSceneStore } from '../store/sceneStore';
import { Inspector } from './Inspector';

const store = () => useSceneStore.getState();
const ID = `sha256-${'1'.repeat(64)}`;

function field(path: string): HTMLElement {
  const el = document.querySelector(`[data-field="${path}"]`);
  if (!el) throw new Error(`no input for ${path}`);
  return el as HTMLElement;
}

describe('the inspector’s textures and glTF models', () => {
  afterEach(() => {
    vi.unstubAllGlobals();
    vi.restoreAllMocks();
  });

  it('sets a checker, edits its size as the other fields (refusing 0), and takes it off again, each one undo step', async () => {
    const user = userEvent.setup();
    resetSceneStore({ objects: [{ type: 'sphere', material: { type: 'plastic', color: '#cc3333' } }] });
    store().select({ kind: 'object', index: 0 });
    render(<Inspector />);
    await user.selectOptions(screen.getByLabelText('Texture'), 'checker');
    expect(store().scene.objects[0].material).toEqual({ type: 'plastic', color: '#cc3333', texture: { type: 'checker', colors: ['#ffffff', '#202020'], size: 0.5 } });
    const size = screen.getByLabelText('Square size');
    await user.clear(size);
    await user.type(size, '0{Enter}');
    expect(size).toHaveAttribute('aria-invalid', 'true');
    expect(store().scene.objects[0].material?.texture).toMatchObject({ size: 0.5 });
    await user.clear(size);
    await user.type(size, '2{Enter}');
    expect(store().scene.objects[0].material?.texture).toMatchObject({ size: 2 });
    expect(field('objects[0].material.texture.colors[1]')).toHaveValue('#202020');
    await user.selectOptions(screen.getByLabelText('Texture'), 'none');
    expect(store().scene.objects[0].material).toEqual({ type: 'plastic', color: '#cc3333' });
    expect(store().past).toHaveLength(3);
  });

  it('asks for a file when Image is chosen without one, and imports the picked image', async () => {
    const user = userEvent.setup();
    resetSceneStore({ objects: [{ type: 'box' }] });
    store().select({ kind: 'object', index: 0 });
    const importFiles = vi.fn();
    render(
      <ImportContext.Provider value={importFiles}>
        <Inspector />
      </ImportContext.Provider>,
    );
    const click = vi.spyOn(HTMLInputElement.prototype, 'click');
    await user.selectOptions(screen.getByLabelText('Texture'), 'image');
    expect(click).toHaveBeenCalledTimes(1);
    expect(store().past).toHaveLength(0);
    const png = new File(['png'], 'wood.png', { type: 'image/png' });
    await user.upload(screen.getByTestId('pick-texture'), png);
    expect(importFiles).toHaveBeenCalledWith([png]);
  });

  it('shows an image texture’s repeats, and a glTF model’s placement and size without a material', async () => {
    const scene: Scene = {
      objects: [
        { type: 'plane', material: { type: 'chalk', texture: { type: 'image', asset: ID, scale: [4, 2] } } },
        { type: 'gltf', asset: ID, position: [1, 0, 0], scale: 2 },
      ],
    };
    resetSceneStore(scene);
    store().select({ kind: 'object', index: 0 });
    const fetchFn = vi.fn(async () => new Response(new Uint8Array([137, 80, 78, 71]), { headers: { 'Content-Type': 'image/png' } }));
    vi.stubGlobal('fetch', fetchFn);
    vi.spyOn(URL, 'createObjectURL').mockReturnValue('blob:thumbnail');
    vi.spyOn(URL, 'revokeObjectURL').mockImplementation(() => undefined);
    const { unmount } = render(<Inspector />);
    expect(screen.getByLabelText('Repeat u')).toHaveValue(4);
    expect(screen.getByLabelText('Repeat v')).toHaveValue(2);
    // the thumbnail comes from the asset's bytes (the server's, as this browser keeps none here)
    expect(await screen.findByRole('img', { name: `Texture ${ID.slice(0, 15)}…` })).toHaveAttribute('src', 'blob:thumbnail');
    expect(fetchFn).toHaveBeenCalledWith(`/api/assets/${ID}`, expect.anything());
    unmount();
    meshCache.setModel(ID, { status: 'ready', mesh: boxMesh({ min: [-0.5, 0, -0.25], max: [0.5, 1, 0.25] }) });
    store().select({ kind: 'object', index: 1 });
    render(<Inspector />);
    expect(screen.getByTestId('model-source')).toHaveTextContent(`uploaded glTF ${ID.slice(0, 15)}…, 2 × 2 × 1 m`);
    expect(screen.queryByLabelText('Material type')).toBeNull();
    expect(screen.getByLabelText('Scale')).toHaveValue(2);
  });
});
