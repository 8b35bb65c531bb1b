/**
 * Wavefront OBJ meshes, read as the engine's ObjReader reads them: `v x y z [w]` (w ignored),
 * `vn x y z`, `f` with corners `i`, `i/j`, `i//k` or `i/j/k`, negative (relative) indices, polygons
 * fanned into triangles around their first corner. `vt`, `o`, `g`, `s`, `usemtl`, `mtllib`,
 * comments and any other statement are ignored. Vertex normals are kept only if every face corner
 * names one (a position used with several normals becomes several vertices); otherwise the mesh is
 * shaded flat. Pure: no three.js, no DOM.
 */
import type { MeshObject, Vec3 } from './types';
import { applyMat3, rotationMatrixXYZ } from './vec';

/** A mesh in its own (object) space, ready for a three.js BufferGeometry. */
export interface ParsedObj {
  /** x, y, z per vertex. */
  positions: Float32Array;
  /** Three vertex indices per triangle (counter-clockwise seen from outside, as in OBJ). */
  indices: Uint32Array;
  /** x, y, z per vertex (not necessarily unit length), when the OBJ gives every corner a normal. */
  normals?: Float32Array;
  triangleCount: number;
}

/** An axis-aligned box. */
export interface Bounds {
  min: Vec3;
  max: Vec3;
}

/** OBJ text that cannot be read as a mesh; the message starts with `line N: `. */
export class ObjError extends Error {
  /** The 1-based line of the problem. */
  readonly line: number;

  constructor(line: number, problem: string) {
    super(`line ${line}: ${problem}`);
    this.name = 'ObjError';
    this.line = line;
  }
}

const NUMBER = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;
const INDEX = /^[+-]?\d{1,10}$/;
const WHITESPACE = /\s+/;

/** Reads OBJ text; throws an {@link ObjError} naming the line of the first problem. */
export function parseObj(text: string): ParsedObj {
  const reader = new ObjReader(text);
  while (!reader.done) reader.read(Infinity);
  return reader.finish();
}

/** How {@link parseObjInChunks} shares the thread: a clock, a pause, and how often to look at the clock. */
export interface ChunkOptions {
  /** Milliseconds of work before the reader pauses (default 25: far below a 200 ms long task). */
  budgetMs?: number;
  /** Lines read between two looks at the clock (default 2,000). */
  linesPerCheck?: number;
  /** The clock (default `performance.now`). */
  now?: () => number;
  /** Gives the thread back for a moment (default: a macrotask, so input and painting happen). */
  pause?: () => Promise<void>;
  /** Called after each slice with the fraction of the text read, 0..1, rising; 1 once at the end. */
  onProgress?: (fraction: number) => void;
  /** Stops the reading: the promise rejects with the signal's reason. */
  signal?: AbortSignal;
}

const macrotask = () => new Promise<void>((resolve) => setTimeout(resolve, 0));

/**
 * Reads OBJ text as {@link parseObj} does, in slices of about `budgetMs` each with a pause between
 * them, so a 200,000-triangle file never holds the page for long, reporting the fraction read.
 */
export async function parseObjInChunks(text: string, options: ChunkOptions = {}): Promise<ParsedObj> {
  const { budgetMs = 25, linesPerCheck = 2000, now = () => performance.now(), pause = macrotask, onProgress, signal } = options;
  const reader = new ObjReader(text);
  while (!reader.done) {
    signal?.throwIfAborted();
    const started = now();
    do reader.read(linesPerCheck);
    while (!reader.done && now() - started < budgetMs);
    onProgress?.(reader.done ? 1 : reader.fraction);
    if (!reader.done) await pause();
  }
  signal?.throwIfAborted();
  return reader.finish();
}

/** The OBJ statements read so far; {@link read} takes the next lines, {@link finish} builds the mesh. */
class ObjReader {
  private readonly positions: number[] = [];
  private readonly normals: number[] = [];
  private readonly cornerPositions: number[] = [];
  private readonly cornerNormals: number[] = [];
  private everyCornerHasNormal = true;
  private line = 0;
  private start = 0;

  constructor(private readonly text: string) {}

  /** True once every line has been read. */
  get done(): boolean {
    return this.start > this.text.length;
  }

  /** The fraction of the text's characters read. */
  get fraction(): number {
    return this.text.length === 0 ? 1 : Math.min(1, this.start / this.text.length);
  }

  /** Reads up to `maxLines` more lines; throws an {@link ObjError} at the first bad one. */
  read(maxLines: number): void {
    const { text, positions, normals, cornerPositions, cornerNormals } = this;
    for (let n = 0; n < maxLines && this.start <= text.length; n++) {
      let end = text.indexOf('\n', this.start);
      if (end < 0) end = text.length;
      const line = ++this.line;
      const raw = text.slice(this.start, end);
      const hash = raw.indexOf('#');
      const content = (hash >= 0 ? raw.slice(0, hash) : raw).trim();
      this.start = end + 1;
      if (content === '') continue;
      const tokens = content.split(WHITESPACE);
      const keyword = tokens[0];
      if (keyword === 'v') {
        for (let k = 1; k <= 3; k++) positions.push(coordinate(tokens[k], 'vertex', line));
      } else if (keyword === 'vn') {
        const n = [1, 2, 3].map((k) => coordinate(tokens[k], 'normal', line));
        if (n[0] === 0 && n[1] === 0 && n[2] === 0) throw new ObjError(line, 'normal has zero length');
        normals.push(n[0], n[1], n[2]);
      } else if (keyword === 'f') {
        const corners = tokens.length - 1;
        if (corners < 3) throw new ObjError(line, `face has ${corners} ${corners === 1 ? 'vertex' : 'vertices'}, needs at least 3`);
        const ps: number[] = [];
        const ns: number[] = [];
        for (let k = 1; k <= corners; k++) {
          const parts = tokens[k].split('/');
          if (parts.length > 3) throw new ObjError(line, `'${tokens[k]}' is not a valid face corner`);
          ps.push(resolve(index(parts[0], tokens[k], line), positions.length / 3, 'vertex', line));
          if (parts[1]) index(parts[1], tokens[k], line); // texture index: checked for form, unused
          const m = parts[2] === undefined ? -1 : resolve(index(parts[2], tokens[k], line), normals.length / 3, 'normal', line);
          if (m < 0) this.everyCornerHasNormal = false;
          ns.push(m);
        }
        for (let k = 1; k + 1 < corners; k++) {
          cornerPositions.push(ps[0], ps[k], ps[k + 1]);
          cornerNormals.push(ns[0], ns[k], ns[k + 1]);
        }
      }
    }
  }

  /** The mesh of everything read. */
  finish(): ParsedObj {
    return result(this.positions, this.normals, this.cornerPositions, this.cornerNormals, this.everyCornerHasNormal);
  }
}

function coordinate(token: string | undefined, what: string, line: number): number {
  if (token === undefined) throw new ObjError(line, `${what} needs 3 coordinates`);
  if (!NUMBER.test(token)) throw new ObjError(line, `'${token}' is not a number`);
  const value = Number(token);
  if (!Number.isFinite(value)) throw new ObjError(line, `${what} coordinate '${token}' is not finite`);
  return value;
}

function index(part: string, token: string, line: number): number {
  if (!INDEX.test(part)) throw new ObjError(line, `'${token}' is not a valid index`);
  return Number(part);
}

/** A 1-based or negative (relative) OBJ index as a 0-based index below `count`. */
function resolve(i: number, count: number, what: 'vertex' | 'normal', line: number): number {
  if (i === 0) throw new ObjError(line, `${what} index 0 is not valid (OBJ indices start at 1)`);
  const resolved = i > 0 ? i - 1 : count + i;
  if (resolved < 0 || resolved >= count) {
    const things = what === 'vertex' ? (count === 1 ? 'vertex' : 'vertices') : count === 1 ? 'normal' : 'normals';
    throw new ObjError(line, `${what === 'vertex' ? '' : 'normal '}index ${i} out of range (${count} ${things} so far)`);
  }
  return resolved;
}

function result(positions: number[], normals: number[], cornerPositions: number[], cornerNormals: number[], withNormals: boolean): ParsedObj {
  const triangleCount = cornerPositions.length / 3;
  if (!withNormals || triangleCount === 0) {
    return { positions: Float32Array.from(positions), indices: Uint32Array.from(cornerPositions), triangleCount };
  }
  if (normals.length === positions.length && cornerPositions.every((p, c) => p === cornerNormals[c])) {
    // f v//v ...: normal i belongs to vertex i, as OBJ writers usually arrange it.
    return { positions: Float32Array.from(positions), indices: Uint32Array.from(cornerPositions), normals: Float32Array.from(normals), triangleCount };
  }
  // Otherwise a vertex is a (position, normal) pair, numbered in order of first use.
  const pairs = new Map<number, number>();
  const outPositions: number[] = [];
  const outNormals: number[] = [];
  const indices = new Uint32Array(cornerPositions.length);
  const normalCount = normals.length / 3;
  cornerPositions.forEach((p, c) => {
    const n = cornerNormals[c];
    const key = p * normalCount + n;
    let v = pairs.get(key);
    if (v === undefined) {
      v = pairs.size;
      pairs.set(key, v);
      outPositions.push(positions[3 * p], positions[3 * p + 1], positions[3 * p + 2]);
      outNormals.push(normals[3 * n], normals[3 * n + 1], normals[3 * n + 2]);
    }
    indices[c] = v;
  });
  return { positions: Float32Array.from(outPositions), indices, normals: Float32Array.from(outNormals), triangleCount };
}

/** Where a mesh is put: defaults (origin, scale 1, no rotation) where unset. */
export type MeshPlacement = Pick<MeshObject, 'position' | 'scale' | 'rotation'>;

/** Bounds of the mesh scaled and rotated about its origin, remembered per mesh for its last placement. */
const placedAtOrigin = new WeakMap<ParsedObj, { key: string; bounds: Bounds }>();

/**
 * The world-space axis-aligned bounds of a placed mesh: every vertex v goes to
 * `position + R(rotation) · (scale · v)`. A mesh without vertices is the point at its position.
 * Moving a mesh costs nothing more than an addition (the rotated bounds are remembered).
 */
export function meshBounds(mesh: MeshPlacement, parsed: ParsedObj): Bounds {
  const position = mesh.position ?? [0, 0, 0];
  const scale = mesh.scale ?? 1;
  const rotation = mesh.rotation ?? [0, 0, 0];
  const key = `${scale}|${rotation.join(',')}`;
  let cached = placedAtOrigin.get(parsed);
  if (cached?.key !== key) {
    cached = { key, bounds: rotatedBounds(parsed.positions, scale, rotation) };
    placedAtOrigin.set(parsed, cached);
  }
  const { min, max } = cached.bounds;
  return { min: [0, 1, 2].map((k) => min[k] + position[k]) as Vec3, max: [0, 1, 2].map((k) => max[k] + position[k]) as Vec3 };
}

function rotatedBounds(positions: Float32Array, scale: number, rotation: Vec3): Bounds {
  if (positions.length === 0) return { min: [0, 0, 0], max: [0, 0, 0] };
  const m = rotationMatrixXYZ(rotation);
  const min: Vec3 = [Infinity, Infinity, Infinity];
  const max: Vec3 = [-Infinity, -Infinity, -Infinity];
  for (let i = 0; i < positions.length; i += 3) {
    const p = applyMat3(m, [scale * positions[i], scale * positions[i + 1], scale * positions[i + 2]]);
    for (let k = 0; k < 3; k++) {
      if (p[k] < min[k]) min[k] = p[k];
      if (p[k] > max[k]) max[k] = p[k];
    }
  }
  return { min, max };
}

/**
 * The uniform scale that makes the mesh's largest bounding-box side about `size` metres (three
 * significant digits, so the inspector shows a tidy number); 1 for a mesh without extent.
 */
export function scaleToFit(parsed: ParsedObj, size = 2): number {
  const { min, max } = meshBounds({}, parsed);
  const largest = Math.max(max[0] - min[0], max[1] - min[1], max[2] - min[2]);
  if (!(largest > 0) || !Number.isFinite(largest)) return 1;
  return Number((size / largest).toPrecision(3));
}

/** A box as a mesh of 12 triangles (a glTF model's bounds, for the views, picking and placement). */
export function boxMesh({ min, max }: Bounds): ParsedObj {
  const positions = new Float32Array(24);
  for (let i = 0; i < 8; i++) {
    positions[3 * i] = i & 1 ? max[0] : min[0];
    positions[3 * i + 1] = i & 2 ? max[1] : min[1];
    positions[3 * i + 2] = i & 4 ? max[2] : min[2];
  }
  // two triangles per face, counter-clockwise seen from outside
  const faces = [[0, 4, 6, 2], [1, 3, 7, 5], [0, 1, 5, 4], [2, 6, 7, 3], [0, 2, 3, 1], [4, 5, 7, 6]];
  const indices = new Uint32Array(faces.flatMap(([a, b, c, d]) => [a, b, c, a, c, d]));
  return { positions, indices, triangleCount: 12 };
}
