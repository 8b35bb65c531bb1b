import { render, screen } from '@testing-library/react';
import userEvent from '@testing-library/user-event';
import { describe, expect, it, vi } from 'vitest';
import { frameHeader } from '../test/liveFakes';
import { LiveCanvas } from './LiveCanvas';
import type { LiveConnection } from './liveSession';
import type { FrameHeader } from './protocol';

const BOX = { width: 400, height: 300, left: 20, top: 0 };

function renderCanvas(connection: LiveConnection, frame: FrameHeader | null = frameHeader({ pass: 2, width: 100, height: 75, millis: 40 })) {
  const onReconnect = vi.fn();
  render(<LiveCanvas canvasRef={() => {}} box={BOX} frame={frame} sentRevision={7} connection={connection} onReconnect={onReconnect} />);
  return onReconnect;
}

describe('LiveCanvas', () => {
  it('places the canvas in the letterboxed box and names the frame it shows', () => {
    renderCanvas({ state: 'open' }, frameHeader({ revision: 7, pass: 5, final: true, samplesPerPixel: 16, width: 400, height: 300, millis: 900 }));
    const canvas = screen.getByRole('img');
    expect(canvas).toHaveStyle({ left: '20px', top: '0px', width: '400px', height: '300px' });
    expect(canvas).toHaveAttribute('data-revision', '7');
    expect(canvas).toHaveAttribute('data-sent-revision', '7');
    expect(canvas).toHaveAttribute('data-final', 'true');
    expect(screen.getByRole('status')).toHaveTextContent('final · 16 spp · 400x300 · 900 ms');
  });

  it('says it is connecting before the first frame, and nothing more once frames come', () => {
    renderCanvas({ state: 'connecting' }, null);
    expect(screen.getByTestId('ray-traced-status')).toHaveTextContent('Connecting to the renderer…');
  });

  it('keeps the last frame while reconnecting, and says when it tries again', () => {
    renderCanvas({ state: 'retrying', reason: 'the connection was refused or lost', delayMillis: 2000 });
    expect(screen.getByTestId('ray-traced-status')).toHaveTextContent('pass 2 · 1 spp · 100x75 · 40 ms');
    expect(screen.getByTestId('ray-traced-status')).toHaveTextContent('Reconnecting in 2 s (the connection was refused or lost)');
    expect(screen.queryByRole('button', { name: 'Reconnect' })).toBeNull();
  });

  it('offers Reconnect once it gave up', async () => {
    const onReconnect = renderCanvas({ state: 'failed', reason: 'too many sessions' });
    expect(screen.getByTestId('ray-traced-status')).toHaveTextContent('The live view lost the server: too many sessions.');
    await userEvent.setup().click(screen.getByRole('button', { name: 'Reconnect' }));
    expect(onReconnect).toHaveBeenCalledOnce();
  });
});
