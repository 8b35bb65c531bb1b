import { act, render, screen } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { afterEach, describe, expect, it, vi } from 'vitest';
import { useAutosaveStatus } from '../store/autosave';
import { AutosaveNotice } from './AutosaveNotice';

describe('AutosaveNotice', () => {
  afterEach(() => useAutosaveStatus.setState({ state: 'starting' }, true));

  it('shows nothing while autosave keeps the scene, and says so with Save when it does not', async () => {
    useAutosaveStatus.setState({ state: 'saved' }, true);
    render(<AutosaveNotice />);
    expect(screen.queryByRole('alert')).toBeNull();
    act(() => useAutosaveStatus.setState({ state: 'failed', message: 'Your latest changes are not kept in this browser: full.' }, true));
    expect(screen.getByRole('alert')).toHaveTextContent('Your latest changes are not kept in this browser: full.');
    const click = vi.spyOn(HTMLAnchorElement.prototype, 'click').mockImplementation(() => undefined);
    await userEvent.click(screen.getByRole('button', { name: 'Save' }));
    expect(click).toHaveBeenCalledTimes(1);
    act(() => useAutosaveStatus.setState({ state: 'saved' }, true));
    expect(screen.queryByRole('alert')).toBeNull();
  });
});
