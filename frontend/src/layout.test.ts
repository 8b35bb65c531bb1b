import { describe, expect, it } from 'vitest';
import { initialPanels } from './layout';

describe('initialPanels', () => {
  it('starts narrow windows without the 2D views, so the image keeps the width', () => {
    expect(initialPanels(1024)).toEqual({ views: false, inspector: true });
    expect(initialPanels(800)).toEqual({ views: false, inspector: true });
    expect(initialPanels(1440)).toEqual({ views: true, inspector: true });
  });
});
