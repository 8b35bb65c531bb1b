import { describe, expect, it } from 'vitest';
import { encodeFrame, frameHeader } from '../test/liveFakes';
import { decodeFrame, decodeProblem, encodeNext, encodeRevision, FrameError, isSameOrNewer, previewUrl } from './protocol';

/** A message of raw bytes. */
const bytes = (...values: number[]) => new Uint8Array(values).buffer;

/** A frame whose first four bytes say `length`, followed by `rest`. */
function withLength(length: number, rest: Uint8Array): ArrayBuffer {
  const out = new Uint8Array(4 + rest.length);
  new DataView(out.buffer).setUint32(0, length, false);
  out.set(rest, 4);
  return out.buffer;
}

describe('encodeRevision', () => {
  it('writes revision, scene and view size as one JSON object', () => {
    const scene = { objects: [{ type: 'sphere', radius: 1 }] };
    expect(JSON.parse(encodeRevision({ revision: 7, scene, width: 640, height: 480 }))).toEqual({ revision: 7, scene, width: 640, height: 480 });
  });

  it('leaves out a size it was not given (the server then uses the scene image size)', () => {
    expect(JSON.parse(encodeRevision({ revision: 1, scene: { objects: [] } }))).toEqual({ revision: 1, scene: { objects: [] } });
  });
});

describe('decodeFrame', () => {
  it('splits header and image and names the media type', () => {
    const image = new Uint8Array([137, 80, 78, 71, 1, 2, 3]);
    const header = frameHeader({ revision: 3, pass: 5, width: 640, height: 480, samplesPerPixel: 16, final: true, format: 'png', millis: 1234 });
    const frame = decodeFrame(encodeFrame(header, image));
    expect(frame.header).toEqual(header);
    expect(frame.mediaType).toBe('image/png');
    expect([...frame.image]).toEqual([...image]);
    expect(decodeFrame(encodeFrame(frameHeader({ format: 'jpeg' }))).mediaType).toBe('image/jpeg');
  });

  it('reads the header length big-endian and in bytes, not characters', () => {
    // a header longer than 255 bytes needs the length's upper bytes; "é" is two bytes in UTF-8
    const header = { ...frameHeader({ revision: 9 }), note: 'é'.repeat(200) };
    const frame = decodeFrame(encodeFrame(header, new Uint8Array([42])));
    expect(frame.header.revision).toBe(9);
    expect([...frame.image]).toEqual([42]);
  });

  it('ignores header members it does not know', () => {
    expect(decodeFrame(encodeFrame({ ...frameHeader(), tiles: 4 })).header).toEqual(frameHeader());
  });

  it.each([
    ['an empty message', bytes()],
    ['one byte', bytes(0)],
    ['three bytes', bytes(0, 0, 1)],
  ])('refuses a message too short for its header length: %s', (_, message) => {
    expect(() => decodeFrame(message)).toThrow(FrameError);
    expect(() => decodeFrame(message)).toThrow(/too short/);
  });

  it('refuses a header length past the end of the message, or of zero', () => {
    const json = new TextEncoder().encode(JSON.stringify(frameHeader()));
    expect(() => decodeFrame(withLength(json.length + 1, json))).toThrow(/does not fit/);
    expect(() => decodeFrame(withLength(0xffffffff, json))).toThrow(/does not fit/);
    expect(() => decodeFrame(withLength(0, json))).toThrow(/does not fit/);
  });

  it('refuses a frame without image bytes', () => {
    const json = new TextEncoder().encode(JSON.stringify(frameHeader()));
    expect(() => decodeFrame(withLength(json.length, json))).toThrow(/no image/);
  });

  it('refuses a header that is not JSON, not UTF-8, or not an object', () => {
    const image = new Uint8Array([1]);
    const text = (s: string) => new TextEncoder().encode(s);
    const concat = (a: Uint8Array, b: Uint8Array) => new Uint8Array([...a, ...b]);
    expect(() => decodeFrame(withLength(9, concat(text('{"revisio'), image)))).toThrow(/not UTF-8 JSON/);
    expect(() => decodeFrame(withLength(3, concat(new Uint8Array([0x22, 0xc3, 0x22]), image)))).toThrow(/not UTF-8 JSON/);
    expect(() => decodeFrame(encodeFrame([frameHeader()]))).toThrow(/not a JSON object/);
    expect(() => decodeFrame(encodeFrame(null))).toThrow(/not a JSON object/);
  });

  it.each([
    ['revision', { revision: -1 }],
    ['revision', { revision: 1.5 }],
    ['revision', { revision: '1' }],
    ['pass', { pass: undefined }],
    ['width', { width: 0 }],
    ['height', { height: null }],
    ['samplesPerPixel', { samplesPerPixel: 0 }],
    ['final', { final: 'true' }],
    ['format', { format: 'webp' }],
    ['millis', { millis: -3 }],
  ])('refuses a header whose %s is %j', (field, patch) => {
    expect(() => decodeFrame(encodeFrame({ ...frameHeader(), ...patch }))).toThrow(new RegExp(`header's ${field} is missing or invalid`));
  });
});

describe('decodeProblem', () => {
  it("reads a refused revision's problem as the REST client does, field errors by JSON path", () => {
    const problem = decodeProblem(
      JSON.stringify({
        revision: 4,
        problem: {
          type: 'about:blank',
          title: 'Invalid scene',
          status: 400,
          detail: 'The scene has 1 invalid field.',
          errors: [{ field: 'objects[0].radius', message: 'must be greater than 0' }],
        },
      }),
    );
    expect(problem?.revision).toBe(4);
    expect(problem?.error).toMatchObject({ status: 400, title: 'Invalid scene', detail: 'The scene has 1 invalid field.' });
    expect(problem?.error.errors).toEqual([{ field: 'objects[0].radius', message: 'must be greater than 0' }]);
  });

  it('reads a problem that names no revision (a message the server could not read whole)', () => {
    const problem = decodeProblem(JSON.stringify({ revision: null, problem: { title: 'Service Unavailable', status: 503, detail: 'busy' } }));
    expect(problem?.revision).toBeNull();
    expect(problem?.error).toMatchObject({ status: 503, detail: 'busy' });
  });

  it.each([['not json'], ['[]'], ['{"problem": {"title": "x"}}'], ['{"revision": 2}'], ['{"revision": 2, "problem": "bad"}']])(
    'passes over a text message that is no problem: %s',
    (text) => expect(decodeProblem(text)).toBeNull(),
  );
});

describe('previewUrl', () => {
  it("is /api/preview on the page's host, secure under https", () => {
    expect(previewUrl({ protocol: 'http:', host: 'localhost:5173' })).toBe('ws://localhost:5173/api/preview');
    expect(previewUrl({ protocol: 'https:', host: 'studio.example' })).toBe('wss://studio.example/api/preview');
  });
});

describe('isSameOrNewer', () => {
  it('orders frames by revision, then pass', () => {
    expect(isSameOrNewer({ revision: 1, pass: 1 }, null)).toBe(true);
    expect(isSameOrNewer({ revision: 2, pass: 1 }, { revision: 1, pass: 5 })).toBe(true);
    expect(isSameOrNewer({ revision: 2, pass: 3 }, { revision: 2, pass: 3 })).toBe(true);
    expect(isSameOrNewer({ revision: 2, pass: 2 }, { revision: 2, pass: 3 })).toBe(false);
    expect(isSameOrNewer({ revision: 1, pass: 9 }, { revision: 2, pass: 1 })).toBe(false);
  });
});

describe('encodeNext', () => {
  const size = { width: 64, height: 48 };
  const base = { revision: 4, scene: { name: 'a', objects: [{ type: 'sphere', center: [0, 1, 0] }] } };

  it('sends the whole scene when the server holds no base', () => {
    expect(JSON.parse(encodeNext(5, base.scene, size, null).text)).toEqual({ revision: 5, scene: base.scene, ...size });
  });

  it('sends a patch to the base when it is short', () => {
    const scene = { ...base.scene, objects: [{ type: 'sphere', center: [2, 1, 0] }] };
    const { text, patched } = encodeNext(5, scene, size, base);
    expect(patched).toBe(true);
    expect(JSON.parse(text)).toEqual({ revision: 5, base: 4, ...size, patch: [{ op: 'replace', path: '/objects/0/center', value: [2, 1, 0] }] });
  });

  it('sends the whole scene when the patch would be longer, or past the server bound on operations', () => {
    const many = (value: number, count: number) => ({ objects: Array.from({ length: count }, () => ({ a: value })) });
    const longer = encodeNext(5, many(1, 900), size, { revision: 4, scene: many(0, 900) });
    expect(longer.patched).toBe(false);
    expect(JSON.parse(longer.text).scene).toEqual(many(1, 900));
    const tooMany = encodeNext(5, { objects: Array.from({ length: 1001 }, (_, i) => ({ a: i, long: 'x'.repeat(100) })) }, size, {
      revision: 4,
      scene: { objects: Array.from({ length: 1001 }, () => ({ a: -1, long: 'x'.repeat(100) })) },
    });
    expect(tooMany.patched).toBe(false);
    // a patch longer than the weighing threshold but shorter than the scene still goes as a patch
    const big = { objects: [{ name: 'y'.repeat(20_000) }, { name: 'z'.repeat(30_000) }] };
    const renamed = encodeNext(5, { objects: [{ name: 'w'.repeat(20_000) }, big.objects[1]] }, size, { revision: 4, scene: big });
    expect(renamed.patched).toBe(true);
  });
});
