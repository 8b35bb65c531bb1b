import { describe, expect, it } from 'vitest';
import { HISTORY_KEY, loadHistory, saveHistory } from './historyStorage';
import { persistSceneStore, useSceneStore } from './sceneStore';
import { STARTER_SCENE } from '../model/starterScene';
import type { Scene } from '../model/types';

const store = () => useSceneStore.getState();

describe('undo history across a reload', () => {
  it('keeps undo and redo for the same scene in sessionStorage, and undo works after the reload', () => {
    const stop = persistSceneStore();
    store().setName('one');
    store().setName('two');
    store().setName('three');
    store().undo();
    stop();
    // the reload: a fresh store holding the saved scene, then persistence picks the history up
    useSceneStore.setState({ past: [], future: [] });
    const again = persistSceneStore();
    expect(store().scene.name).toBe('two');
    expect(store().past.map((s) => s.name)).toEqual(['still-life', 'one']);
    expect(store().future.map((s) => s.name)).toEqual(['three']);
    store().undo();
    expect(store().scene.name).toBe('one');
    again();
  });

  it('ignores a history that belongs to another scene, and drops the oldest steps over the budget', () => {
    const scene = (name: string, pad = 0): Scene => ({ name, objects: [{ type: 'sphere', name: 'x'.repeat(pad) }] });
    saveHistory(scene('now'), [scene('a')], []);
    expect(loadHistory(scene('other'))).toEqual({ past: [], future: [] });
    saveHistory(scene('now'), [scene('old', 500), scene('mid', 500), scene('new', 500)], [scene('redo')], sessionStorage, 1400);
    const kept = loadHistory(scene('now'));
    expect(kept.past.map((s) => s.name)).toEqual(['mid', 'new']);
    expect(kept.future.map((s) => s.name)).toEqual(['redo']);
    expect(sessionStorage.getItem(HISTORY_KEY)!.length).toBeLessThanOrEqual(1400 + 100);
    expect(STARTER_SCENE.name).toBe('still-life');
  });
});
