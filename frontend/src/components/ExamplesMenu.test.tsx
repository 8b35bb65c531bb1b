import { render, screen } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { describe, expect, it, vi } from 'vitest';
import { ExamplesMenu } from './ExamplesMenu';

describe('ExamplesMenu', () => {
  it('closes on Escape, handing focus back to its button, and on a press elsewhere', async () => {
    const user = userEvent.setup();
    const onPick = vi.fn();
    render(<ExamplesMenu scenes={[{ name: 'still-life' } as never]} loading={false} onPick={onPick} />);
    const summary = screen.getByText('Examples');
    const menu = summary.closest('details')!;
    await user.click(summary);
    expect(menu.open).toBe(true);
    await user.keyboard('{Escape}');
    expect(menu.open).toBe(false);
    expect(document.activeElement).toBe(summary);
    await user.click(summary);
    expect(menu.open).toBe(true);
    await user.click(document.body);
    expect(menu.open).toBe(false);
    expect(onPick).not.toHaveBeenCalled();
  });
});
