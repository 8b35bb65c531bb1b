/**
 * One finished render as the history keeps it: the image, what it is a render of (the exact scene
 * sent), and what the stage and the history strip say about it. Pure: no React, no storage.
 */
import { SCENE_DEFAULTS } from '../../model/defaults';
import type { Scene } from '../../model/types';
import { validateScene } from '../../model/validate';
import { formatMillis } from '../format';

/** A render of the history; a plain value, stored as it is (IndexedDB keeps the Blobs). */
export interface RenderRecord {
  /** Unique in this browser: the time it finished and the server's job id. */
  id: string;
  /** The server's id of the job that rendered it (the stage knows its own render by it). */
  jobId: string;
  /** 1, 2, 3…: shown as "Render 3"; counts on across reloads (the highest kept plus one). */
  number: number;
  /** When the job finished, in epoch milliseconds of this browser's clock. */
  finishedAt: number;
  /** The server's render time. */
  renderMillis: number;
  raysPerSecond: number | null;
  /** Image size in pixels. */
  width: number;
  height: number;
  /** Samples per pixel asked for; with adaptive sampling the most a pixel took. */
  samples: number;
  adaptive: boolean;
  /** The scene's `name`, as the download is named. */
  sceneName: string;
  /** The download's file name, e.g. `still-life.png`. */
  filename: string;
  /** The scene exactly as it was sent: what "Restore scene" puts back. */
  scene: Scene;
  /** The image as the server sent it (PNG or JPEG). */
  image: Blob;
  /** A small copy for the history strip; null when none could be made (the image stands in). */
  thumbnail: Blob | null;
}

/** What a finished job gives the history: everything of a record but its number and thumbnail. */
export interface FinishedRender {
  jobId: string;
  finishedAt: number;
  /** The scene as the panel sent it: its JSON value, or JSON text. */
  sentScene: unknown;
  image: Blob;
  filename: string;
  width: number;
  height: number;
  renderMillis: number;
  raysPerSecond: number | null;
}

/**
 * The scene a render was made of, as a scene value: JSON text is parsed; null when the value has no
 * scene's shape (then the render is not kept, since its scene could not be restored).
 */
export function sceneOfSent(sent: unknown): Scene | null {
  let value = sent;
  if (typeof sent === 'string') {
    try {
      value = JSON.parse(sent);
    } catch {
      return null;
    }
  }
  const result = validateScene(value);
  return result.ok ? structuredClone(result.scene) : null;
}

/** The record of a finished render, or null when what was sent is no scene. */
export function recordOf(render: FinishedRender, number: number, thumbnail: Blob | null = null): RenderRecord | null {
  const scene = sceneOfSent(render.sentScene);
  if (!scene) return null;
  return {
    id: `${render.finishedAt.toString(36)}-${render.jobId}`,
    jobId: render.jobId,
    number,
    finishedAt: render.finishedAt,
    renderMillis: render.renderMillis,
    raysPerSecond: render.raysPerSecond,
    width: render.width,
    height: render.height,
    samples: scene.render?.samples ?? SCENE_DEFAULTS.render.samples,
    adaptive: (scene.render?.adaptive ?? SCENE_DEFAULTS.render.adaptive) > 0,
    sceneName: scene.name ?? SCENE_DEFAULTS.name,
    filename: render.filename,
    scene,
    image: render.image,
    thumbnail,
  };
}

/**
 * A stored value read back as a record, or null when it is not one (a record of an older version of
 * the editor, or damaged storage): such values are dropped rather than shown half.
 */
export function readRecord(value: unknown): RenderRecord | null {
  if (typeof value !== 'object' || value === null) return null;
  const r = value as Record<string, unknown>;
  const numbers = [r.number, r.finishedAt, r.renderMillis, r.width, r.height, r.samples];
  if (!numbers.every((n) => typeof n === 'number' && Number.isFinite(n))) return null;
  if (typeof r.id !== 'string' || typeof r.jobId !== 'string' || typeof r.sceneName !== 'string' || typeof r.filename !== 'string') return null;
  if (typeof r.adaptive !== 'boolean' || !(r.image instanceof Blob)) return null;
  if (r.raysPerSecond !== null && typeof r.raysPerSecond !== 'number') return null;
  if (r.thumbnail !== null && !(r.thumbnail instanceof Blob)) return null;
  const scene = validateScene(r.scene);
  return scene.ok ? (value as RenderRecord) : null;
}

/** "Render 3". */
export function recordTitle(record: RenderRecord): string {
  return `Render ${record.number}`;
}

/** "16 spp", or "up to 16 spp" with adaptive sampling. */
export function formatSamples(samples: number, adaptive: boolean): string {
  return adaptive ? `up to ${samples} spp` : `${samples} spp`;
}

/** The time of day as 14:03:12; another day's as 2024-05-01 14:03. Local time. */
export function formatFinished(finishedAt: number, now: number = Date.now()): string {
  const at = new Date(finishedAt);
  const today = new Date(now);
  const pad = (n: number) => String(n).padStart(2, '0');
  const time = `${pad(at.getHours())}:${pad(at.getMinutes())}`;
  const sameDay = at.getFullYear() === today.getFullYear() && at.getMonth() === today.getMonth() && at.getDate() === today.getDate();
  return sameDay ? `${time}:${pad(at.getSeconds())}` : `${at.getFullYear()}-${pad(at.getMonth() + 1)}-${pad(at.getDate())} ${time}`;
}

/** A render's caption on the stage: "Render 2 · 14:03:12 · up to 16 spp". */
export function recordCaption(record: RenderRecord, now: number = Date.now()): string {
  return `${recordTitle(record)} · ${formatFinished(record.finishedAt, now)} · ${formatSamples(record.samples, record.adaptive)}`;
}

/** One line on a render: "still-life · 14:03:12 · 800 × 600 px · up to 16 spp · 1.5 s". */
export function recordSummary(record: RenderRecord, now: number = Date.now()): string {
  return [
    record.sceneName,
    formatFinished(record.finishedAt, now),
    `${record.width} × ${record.height} px`,
    formatSamples(record.samples, record.adaptive),
    formatMillis(record.renderMillis),
  ].join(' · ');
}

/** The accessible name of a render: "Render 3: still-life · 14:03:12 · 800 × 600 px · …". */
export function recordName(record: RenderRecord, now: number = Date.now()): string {
  return `${recordTitle(record)}: ${recordSummary(record, now)}`;
}
