/**
 * The wire format of the live ray-traced view, the WebSocket at `/api/preview`. Pure functions,
 * no React, no socket.
 *
 * The client sends text messages, each a new revision: the whole scene,
 * `{"revision": n, "scene": {...}, "width": w, "height": h}` (revisions strictly increasing;
 * the size is the view's in device pixels), or after it a JSON Patch (RFC 6902) to the scene of
 * the revision sent last, `{"revision": n, "base": m, "patch": [...], "width": w, "height": h}`.
 * A patch the server cannot apply gets a problem, and the client sends the whole scene. The
 * server answers each revision with binary
 * frames, coarse to fine: a 4-byte big-endian header length, that many bytes of UTF-8 JSON
 * header, then the encoded image. An invalid scene gets a text message
 * `{"revision": n, "problem": {...}}` holding the REST API's RFC 9457 problem.
 */
import { problemToError, type ApiError } from '../api/client';
import { isRecord } from '../util/json';
import { diffJson, MAX_PATCH_OPERATIONS, type PatchOperation } from './scenePatch';

/** One revision as the client sends it. */
export interface RevisionMessage {
  /** Strictly increasing over the life of the view, across reconnections too. */
  revision: number;
  /** The scene, in the same format as `POST /api/render` takes. */
  scene: unknown;
  /** The view's size in device pixels; the server uses the scene's image size when absent. */
  width?: number;
  height?: number;
}

/** One revision as a patch to the scene of revision `base`, the one sent before it. */
export interface PatchMessage {
  revision: number;
  base: number;
  patch: PatchOperation[];
  width?: number;
  height?: number;
}

/** The JSON header of a frame. */
export interface FrameHeader {
  /** The revision this frame shows. */
  revision: number;
  /** The refinement pass: coarse passes first, each finer than the last. */
  pass: number;
  /** This frame's own size in pixels (coarse passes are smaller than the view). */
  width: number;
  height: number;
  samplesPerPixel: number;
  /** True for the revision's last frame (always PNG). */
  final: boolean;
  format: 'jpeg' | 'png';
  /** The server's time from receiving the revision to sending this frame. */
  millis: number;
}

/** A decoded frame: its header and the encoded image, a view into the message's bytes. */
export interface Frame {
  header: FrameHeader;
  image: Uint8Array<ArrayBuffer>;
  /** The image's media type, from the header's `format`. */
  mediaType: 'image/jpeg' | 'image/png';
}

/** The server's refusal of one revision's scene. */
export interface RevisionProblem {
  /** The revision refused; null when the server could not tell which (a message it could not read whole). */
  revision: number | null;
  /** The problem as the REST client reads it: status, title, detail, field errors by JSON path. */
  error: ApiError;
}

/** A binary message that is not a frame; the message says what is wrong with it. */
export class FrameError extends Error {
  constructor(message: string) {
    super(message);
    this.name = 'FrameError';
  }
}

/** Bytes of the big-endian header length that starts every frame. */
const LENGTH_BYTES = 4;

const UTF8 = new TextDecoder('utf-8', { fatal: true });

/** The text message for one revision; width and height are left out when not given. */
export function encodeRevision({ revision, scene, width, height }: RevisionMessage): string {
  return JSON.stringify({ revision, scene, width, height });
}

/** The text message for a patched revision. */
export function encodePatch({ revision, base, patch, width, height }: PatchMessage): string {
  return JSON.stringify({ revision, base, width, height, patch });
}

/** A patch this long or longer is weighed against the whole scene before it is sent. */
const WEIGH_PATCH_CHARS = 16 * 1024;

/**
 * The message for revision `revision` of `scene`: a patch to `base` (the scene of the revision
 * sent before, which the server holds) when there is one and the patch is within the server's
 * bounds and shorter than the whole scene, else the whole scene.
 */
export function encodeNext(
  revision: number,
  scene: unknown,
  size: { width?: number; height?: number },
  base: { revision: number; scene: unknown } | null,
): { text: string; patched: boolean } {
  const whole = () => encodeRevision({ revision, scene, ...size });
  if (!base) return { text: whole(), patched: false };
  const patch = diffJson(base.scene, scene);
  if (patch.length > MAX_PATCH_OPERATIONS) return { text: whole(), patched: false };
  const text = encodePatch({ revision, base: base.revision, patch, ...size });
  if (text.length < WEIGH_PATCH_CHARS) return { text, patched: true };
  const wholeText = whole();
  return text.length < wholeText.length ? { text, patched: true } : { text: wholeText, patched: false };
}

/** Splits a binary message into header and image; throws a {@link FrameError} if it is not a frame. */
export function decodeFrame(message: ArrayBuffer): Frame {
  if (message.byteLength < LENGTH_BYTES) {
    throw new FrameError(`a frame of ${message.byteLength} bytes is too short for its header length`);
  }
  const headerLength = new DataView(message).getUint32(0, false);
  const imageStart = LENGTH_BYTES + headerLength;
  if (headerLength === 0 || imageStart > message.byteLength) {
    throw new FrameError(`a header of ${headerLength} bytes does not fit a frame of ${message.byteLength} bytes`);
  }
  if (imageStart === message.byteLength) throw new FrameError('the frame has no image');
  let json: unknown;
  try {
    json = JSON.parse(UTF8.decode(new Uint8Array(message, LENGTH_BYTES, headerLength)));
  } catch (cause) {
    throw new FrameError(`the frame header is not UTF-8 JSON (${cause instanceof Error ? cause.message : String(cause)})`);
  }
  const header = parseHeader(json);
  return { header, image: new Uint8Array(message, imageStart), mediaType: header.format === 'png' ? 'image/png' : 'image/jpeg' };
}

/**
 * The problem of a text message, or null for a text message that is not one (ignored, so a
 * server may add kinds of messages later).
 */
export function decodeProblem(text: string): RevisionProblem | null {
  let body: unknown;
  try {
    body = JSON.parse(text);
  } catch {
    return null;
  }
  if (!isRecord(body) || !(isCount(body.revision) || body.revision === null) || !isRecord(body.problem)) return null;
  const status = typeof body.problem.status === 'number' ? body.problem.status : 400;
  return { revision: body.revision, error: problemToError(status, body.problem) };
}

/** The socket's address on the page's own host: `ws://host/api/preview` (`wss:` under https). */
export function previewUrl(location: { protocol: string; host: string }): string {
  return `${location.protocol === 'https:' ? 'wss:' : 'ws:'}//${location.host}/api/preview`;
}

/** True when frame `a` is at least as new as frame `b`: a later revision, or a later pass of the same one. */
export function isSameOrNewer(a: Pick<FrameHeader, 'revision' | 'pass'>, b: Pick<FrameHeader, 'revision' | 'pass'> | null): boolean {
  return b === null || a.revision > b.revision || (a.revision === b.revision && a.pass >= b.pass);
}

function parseHeader(json: unknown): FrameHeader {
  if (!isRecord(json)) throw new FrameError('the frame header is not a JSON object');
  const { revision, pass, width, height, samplesPerPixel, final, format, millis } = json;
  const bad = (field: string) => new FrameError(`the frame header's ${field} is missing or invalid`);
  if (!isCount(revision)) throw bad('revision');
  if (!isCount(pass)) throw bad('pass');
  if (!isCount(width) || width === 0) throw bad('width');
  if (!isCount(height) || height === 0) throw bad('height');
  if (!isCount(samplesPerPixel) || samplesPerPixel === 0) throw bad('samplesPerPixel');
  if (typeof final !== 'boolean') throw bad('final');
  if (format !== 'jpeg' && format !== 'png') throw bad('format');
  if (typeof millis !== 'number' || !Number.isFinite(millis) || millis < 0) throw bad('millis');
  return { revision, pass, width, height, samplesPerPixel, final, format, millis };
}

/** A whole number from 0 up. */
function isCount(value: unknown): value is number {
  return typeof value === 'number' && Number.isSafeInteger(value) && value >= 0;
}
