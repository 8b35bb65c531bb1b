import { fireEvent, render, screen } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { describe, expect, it, vi } from 'vitest';
import { ImageViewer } from './ImageViewer';

describe('ImageViewer', () => {
  it('fits the image, zooms about the cursor, shows 1:1 pixels, and closes on Escape', async () => {
    const user = userEvent.setup();
    const onClose = vi.fn();
    render(<ImageViewer url="blob:x" width={1600} height={1200} name="still-life.png" onClose={onClose} />);
    expect(screen.getByRole('dialog', { name: 'Full-size image still-life.png' })).toBeInTheDocument();
    const image = screen.getByRole('img', { name: 'The render at full size' });
    const scale = () => Number(image.getAttribute('data-scale'));
    expect(scale()).toBe(0.5); // happy-dom lays out nothing: the fallback area of 800 x 600
    fireEvent.wheel(screen.getByTestId('image-viewer-area'), { deltaY: -500, clientX: 100, clientY: 100 });
    expect(scale()).toBeGreaterThan(0.5);
    await user.click(screen.getByRole('button', { name: '1:1' }));
    expect(scale()).toBe(1);
    await user.click(screen.getByRole('button', { name: 'Fit' }));
    expect(scale()).toBe(0.5);
    await user.keyboard('{Escape}');
    expect(onClose).toHaveBeenCalled();
  });
});
