/**
 * The edit from one scene value to the next as a JSON Patch (RFC 6902), for the live view to send
 * instead of the whole scene. The store's scenes are immutable and share what an edit did not
 * touch, so the diff compares by reference first (an unchanged object of 10,000 costs one `===`)
 * and by value only where the references differ. Pure functions, no React, no socket.
 */
import { sameJson } from '../model/sameJson';
import { isRecord } from '../util/json';

/** One operation of the patches this module makes: add, remove or replace. */
export type PatchOperation =
  | { op: 'add'; path: string; value: unknown }
  | { op: 'remove'; path: string }
  | { op: 'replace'; path: string; value: unknown };

/** The most operations a patch may have (the server's bound). */
export const MAX_PATCH_OPERATIONS = 1000;

/**
 * The operations that turn `before` into `after`, both JSON-like values (a field whose value is
 * `undefined` counts as absent, as `JSON.stringify` writes it); empty when they are equal.
 */
export function diffJson(before: unknown, after: unknown): PatchOperation[] {
  const operations: PatchOperation[] = [];
  diff(before, after, '', operations);
  return operations;
}

/** A JSON Pointer token (RFC 6901): `~` as `~0`, `/` as `~1`. */
export function pointerToken(key: string | number): string {
  return String(key).replace(/~/g, '~0').replace(/\//g, '~1');
}

function diff(before: unknown, after: unknown, path: string, out: PatchOperation[]): void {
  if (before === after) return;
  if (Array.isArray(before) && Array.isArray(after) && !(isLeaf(before) && isLeaf(after))) return diffArrays(before, after, path, out);
  if (isRecord(before) && isRecord(after)) return diffObjects(before, after, path, out);
  if (!sameJson(before, after)) out.push({ op: 'replace', path, value: jsonValue(after) });
}

function diffObjects(before: Record<string, unknown>, after: Record<string, unknown>, path: string, out: PatchOperation[]): void {
  for (const key of Object.keys(before)) {
    if (before[key] !== undefined && after[key] === undefined) out.push({ op: 'remove', path: `${path}/${pointerToken(key)}` });
  }
  for (const key of Object.keys(after)) {
    const value = after[key];
    if (value === undefined) continue;
    const at = `${path}/${pointerToken(key)}`;
    if (before[key] === undefined) out.push({ op: 'add', path: at, value });
    else diff(before[key], value, at, out);
  }
}

/**
 * Arrays: the elements both share at the start and at the end (by reference, then by value) stay;
 * those between are changed in place pairwise, and the rest removed (last first) or added.
 */
function diffArrays(before: unknown[], after: unknown[], path: string, out: PatchOperation[]): void {
  let start = 0;
  while (start < before.length && start < after.length && sameJson(before[start], after[start])) start++;
  let endBefore = before.length;
  let endAfter = after.length;
  while (endBefore > start && endAfter > start && sameJson(before[endBefore - 1], after[endAfter - 1])) {
    endBefore--;
    endAfter--;
  }
  const paired = Math.min(endBefore - start, endAfter - start);
  for (let i = start; i < start + paired; i++) diff(before[i], after[i], `${path}/${i}`, out);
  for (let i = endBefore - 1; i >= start + paired; i--) out.push({ op: 'remove', path: `${path}/${i}` });
  for (let i = start + paired; i < endAfter; i++) out.push({ op: 'add', path: `${path}/${i}`, value: jsonValue(after[i]) });
}

/** An array of numbers, strings and such (a vector, a colour list): replaced whole when it changes, in one short operation. */
function isLeaf(array: unknown[]): boolean {
  return array.every((x) => typeof x !== 'object' || x === null);
}

/** `undefined` in an array is written as null. */
function jsonValue(value: unknown): unknown {
  return value === undefined ? null : value;
}
