import { act, renderHook } from '@testing-library/react';
import { afterEach, describe, expect, it } from 'vitest';
import { PANELS_KEY, usePanels } from './usePanels';

describe('usePanels', () => {
  afterEach(() => localStorage.clear());

  it('starts from the window width while the user has not chosen', () => {
    const { result } = renderHook(() => usePanels());
    expect(result.current[0]).toEqual({ views: window.innerWidth >= 1280, inspector: true });
  });

  it('keeps the user\'s choice across a reload', () => {
    const first = renderHook(() => usePanels());
    act(() => first.result.current[1]({ views: true, inspector: false }));
    first.unmount();
    const again = renderHook(() => usePanels());
    expect(again.result.current[0]).toEqual({ views: true, inspector: false });
  });

  it('ignores a stored choice it cannot read', () => {
    localStorage.setItem(PANELS_KEY, '{"views":"yes"}');
    const { result } = renderHook(() => usePanels());
    expect(result.current[0].inspector).toBe(true);
    expect(typeof result.current[0].views).toBe('boolean');
  });
});
