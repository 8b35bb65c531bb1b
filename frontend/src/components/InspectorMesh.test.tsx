import { act, render, screen, waitFor, within } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { describe, expect, it } from 'vitest';
import { meshCache } from '../hooks/useMeshes';
import type { Scene } from '../model/types';
import { resetSceneStore, useSceneStore } from '../store/sceneStore';
import { gridObj, TETRAHEDRON_OBJ } from '../test/meshes';
import { FieldErrorsProvider } from './fieldErrors';
import { Inspector } from './Inspector';

const store = () => useSceneStore.getState();

const SCENE: Scene = {
  name: 'meshes',
  objects: [
    { type: 'sphere' },
    { type: 'mesh', obj: TETRAHEDRON_OBJ, position: [1, 0, 2], scale: 2, rotation: [0, 45, 0], material: { type: 'metal', color: '#aa8800' } },
    { type: 'mesh', file: 'meshes/torus-knot.obj' },
    { type: 'mesh', obj: 'v 0 0 0\nv 1 0 0\nf 1 2 3\n' },
    { type: 'mesh', obj: gridObj(40, 1, 60) },
  ],
};

const objFile = (text: string, name = 'thing.obj') => new File([text], name, { type: '' });

describe('Inspector for a mesh', () => {
  it('edits position, scale and rotation by their JSON paths and shows the material and the triangle count', async () => {
    const user = userEvent.setup();
    resetSceneStore(SCENE);
    store().select({ kind: 'object', index: 1 });
    render(<Inspector />);
    expect(screen.getByRole('heading', { name: 'Mesh 2' })).toBeInTheDocument();
    expect(screen.getByLabelText('Position x')).toHaveAttribute('data-field', 'objects[1].position[0]');
    expect(screen.getByLabelText('Rotation y')).toHaveAttribute('data-field', 'objects[1].rotation[1]');
    expect(screen.getByLabelText('Rotation y')).toHaveValue(45);
    expect(screen.getByLabelText('Material type')).toHaveAttribute('data-field', 'objects[1].material.type');
    expect(screen.getByLabelText('Material type')).toHaveValue('metal');
    expect(screen.getByTestId('mesh-source')).toHaveTextContent('inline OBJ, 4 triangles');
    const scale = screen.getByLabelText('Scale');
    expect(scale).toHaveAttribute('data-field', 'objects[1].scale');
    await user.clear(scale);
    await user.type(scale, '0.5{Enter}');
    expect(store().scene.objects[1]).toMatchObject({ scale: 0.5, position: [1, 0, 2], obj: TETRAHEDRON_OBJ });
    expect(store().past).toHaveLength(1);
    await user.clear(scale);
    await user.type(scale, '0');
    expect(screen.getByText('must be greater than 0')).toHaveClass('field-error');
  });

  it('explains an OBJ it cannot read, naming the line', () => {
    resetSceneStore(SCENE);
    store().select({ kind: 'object', index: 3 });
    render(<Inspector />);
    expect(screen.getByRole('alert')).toHaveTextContent('Cannot read the OBJ: line 3: index 3 out of range (2 vertices so far)');
    expect(screen.getByTestId('mesh-source')).toHaveTextContent(/^Trianglesinline OBJ/);
  });

  it('shows a file mesh’s name read-only, loading until the file arrives, then its triangles', async () => {
    resetSceneStore(SCENE);
    store().select({ kind: 'object', index: 2 });
    render(<Inspector />);
    const source = screen.getByTestId('mesh-source');
    expect(source).toHaveTextContent('file meshes/torus-knot.obj, loading…');
    expect(within(source).queryByRole('textbox')).toBeNull();
    act(() => meshCache.ensure('meshes/torus-knot.obj', async () => gridObj(40, 1, 60)));
    await waitFor(() => expect(source).toHaveTextContent('file meshes/torus-knot.obj, 4,800 triangles'));
  });

  it('replaces the triangles by an inline copy of a local OBJ file, one undo step; refuses a bad file', async () => {
    const user = userEvent.setup();
    resetSceneStore(SCENE);
    store().select({ kind: 'object', index: 2 });
    render(<Inspector />);
    await user.upload(screen.getByTestId('load-obj'), objFile('v 0 0 0\nf 1 1 1 1\nf 9 9 9\n', 'bad.obj'));
    await waitFor(() => expect(screen.getByRole('alert')).toHaveTextContent('Cannot use bad.obj: line 3: index 9 out of range (1 vertex so far)'));
    expect(store().past).toHaveLength(0);
    await user.upload(screen.getByTestId('load-obj'), objFile(TETRAHEDRON_OBJ));
    await waitFor(() => expect(store().scene.objects[2]).toEqual({ type: 'mesh', obj: TETRAHEDRON_OBJ }));
    expect(store().past).toHaveLength(1);
    expect(screen.getByTestId('mesh-source')).toHaveTextContent('inline OBJ, 4 triangles');
    expect(screen.queryByRole('alert')).toBeNull();
  });

  it('lists meshes in the outline with their triangle count', () => {
    resetSceneStore(SCENE);
    render(<Inspector />);
    const outline = screen.getByRole('navigation', { name: 'Scene contents' });
    expect(within(outline).getByRole('button', { name: /Mesh 2 \(4 triangles\)/ })).toBeInTheDocument();
    expect(within(outline).getByRole('button', { name: /Mesh 3 \(loading…\)/ })).toBeInTheDocument();
    expect(within(outline).getByRole('button', { name: /Mesh 4 \(OBJ error\)/ })).toBeInTheDocument();
    expect(within(outline).getByRole('button', { name: /Mesh 5 \(4,800 triangles\)/ })).toBeInTheDocument();
  });

  it('shows the server’s problem with a mesh’s OBJ next to its source', () => {
    resetSceneStore(SCENE);
    store().select({ kind: 'object', index: 2 });
    render(
      <FieldErrorsProvider errors={{ 'objects[2].file': "no mesh 'meshes/torus-knot.obj' ships with this server" }}>
        <Inspector />
      </FieldErrorsProvider>,
    );
    expect(screen.getByTestId('mesh-source')).toHaveTextContent("no mesh 'meshes/torus-knot.obj' ships with this server");
  });
});
