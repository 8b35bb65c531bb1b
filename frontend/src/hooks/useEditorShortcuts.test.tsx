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

  it('copies the selection as scene JSON and pastes it back as one undo step, not inside a field', () => {
    renderHook(() => useEditorShortcuts());
    store().select({ kind: 'object', index: 1 });
    const data = new Map<string, string>();
    const clipboardData = { setData: (t: string, v: string) => data.set(t, v), getData: (t: string) => data.get(t) ?? '' };
    const copy = new Event('copy', { cancelable: true }) as ClipboardEvent;
    Object.defineProperty(copy, 'clipboardData', { value: clipboardData });
    document.dispatchEvent(copy);
    expect(copy.defaultPrevented).toBe(true);
    expect(JSON.parse(data.get('text/plain')!).objects).toEqual([store().scene.objects[1]]);

    const count = store().scene.objects.length;
    const paste = new Event('paste', { cancelable: true }) as ClipboardEvent;
    Object.defineProperty(paste, 'clipboardData', { value: clipboardData });
    document.dispatchEvent(paste);
    expect(store().scene.objects).toHaveLength(count + 1);
    expect(store().selection).toEqual({ kind: 'object', index: count });
    expect(store().past).toHaveLength(1);

    const input = document.createElement('input');
    document.body.appendChild(input);
    const inField = new Event('paste', { bubbles: true, cancelable: true }) as ClipboardEvent;
    Object.defineProperty(inField, 'clipboardData', { value: clipboardData });
    input.dispatchEvent(inField);
    expect(store().scene.objects).toHaveLength(count + 1);
    input.remove();
  });
});
