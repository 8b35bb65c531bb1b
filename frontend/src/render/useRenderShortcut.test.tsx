import { fireEvent, render, renderHook } from '@testing-library/react';
import { describe, expect, it, vi } from 'vitest';
import { useRenderShortcut } from './useRenderShortcut';

describe('useRenderShortcut', () => {
  it('renders on Ctrl+Enter and Cmd+Enter', () => {
    const onRender = vi.fn();
    renderHook(() => useRenderShortcut(onRender));
    fireEvent.keyDown(window, { key: 'Enter', ctrlKey: true });
    fireEvent.keyDown(window, { key: 'Enter', metaKey: true });
    expect(onRender).toHaveBeenCalledTimes(2);
  });

  it('leaves plain Enter, Shift and Alt alone', () => {
    const onRender = vi.fn();
    renderHook(() => useRenderShortcut(onRender));
    fireEvent.keyDown(window, { key: 'Enter' });
    fireEvent.keyDown(window, { key: 'Enter', ctrlKey: true, shiftKey: true });
    fireEvent.keyDown(window, { key: 'Enter', ctrlKey: true, altKey: true });
    expect(onRender).not.toHaveBeenCalled();
  });

  it('leaves a text area its own Ctrl+Enter (the JSON tab applies)', () => {
    const onRender = vi.fn();
    renderHook(() => useRenderShortcut(onRender));
    const { getByRole } = render(<textarea aria-label="json" />);
    fireEvent.keyDown(getByRole('textbox'), { key: 'Enter', ctrlKey: true });
    expect(onRender).not.toHaveBeenCalled();
  });

  it('commits a field being typed in before it renders', async () => {
    const order: string[] = [];
    renderHook(() => useRenderShortcut(() => order.push('render')));
    const { getByRole } = render(<input aria-label="radius" onBlur={() => order.push('commit')} />);
    const field = getByRole('textbox');
    field.focus();
    fireEvent.keyDown(field, { key: 'Enter', ctrlKey: true });
    await new Promise((resolve) => setTimeout(resolve, 5));
    expect(order).toEqual(['commit', 'render']);
  });
});
