import { render, screen } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { describe, expect, it } from 'vitest';
import { Preview3D } from './Preview3D';

describe('Preview3D', () => {
  it('explains itself when WebGL is missing, and toggles between camera and orbit view', async () => {
    const user = userEvent.setup();
    render(<Preview3D />);
    expect(screen.getByRole('note')).toHaveTextContent('needs WebGL');
    const viewport = screen.getByTestId('preview-3d');
    expect(viewport).toHaveAttribute('data-mode', 'camera');
    expect(screen.getByRole('button', { name: 'Camera view' })).toHaveAttribute('aria-pressed', 'true');
    await user.click(screen.getByRole('button', { name: 'Orbit view' }));
    expect(viewport).toHaveAttribute('data-mode', 'orbit');
    expect(screen.getByRole('button', { name: 'Orbit view' })).toHaveAttribute('aria-pressed', 'true');
  });
});
