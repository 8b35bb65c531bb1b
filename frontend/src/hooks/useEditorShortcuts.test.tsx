import { renderHook } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { describe, expect, it } from 'vitest';
import { useSceneStore } from '../store/sceneStore';
import { useEditorShortcuts } from './useEditorShortcuts';

const store = () => useSceneStore.getState();

describe('editor shortcuts', () => {
  it('W, E, R pick the 3D handles and F asks the 3D view to frame the selection, never while typing', async () => {
    const user = userEvent.setup();
    renderHook(() => useEditorShortcuts());
    expect(store().gizmo).toBe('translate');
    await user.keyboard('e');
    expect(store().gizmo).toBe('rotate');
    await user.keyboard('r');
    expect(store().gizmo).toBe('scale');
    await user.keyboard('w');
    expect(store().gizmo).toBe('translate');
    const frames = store().frameRequest;
    await user.keyboard('f');
    expect(store().frameRequest).toBe(frames + 1);

    const input = document.createElement('input');
    document.body.appendChild(input);
    input.focus();
    await user.keyboard('ref');
    expect(store().gizmo).toBe('translate');
    expect(store().frameRequest).toBe(frames + 1);
    input.remove();
  });
});
