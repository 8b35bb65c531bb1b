/**
 * Which of the 3D preview's meshes and lights an update keeps, creates and removes (pure, no
 * three.js). Each entry is known by its object's or light's stable id, so a drag step, a recolour
 * or a deletion elsewhere in the list changes the entries it concerns in place and rebuilds none.
 * An entry is replaced (removed, then created under the same key) when what it was built from
 * changes: a mesh's geometry kind or its triangles; a light's kind, whether it casts a shadow, or
 * whether an area light is two-sided.
 */
import type { LightDescriptor, MeshDescriptor } from '../model/toThree';
import type { ParsedObj } from '../model/obj';

/** Lights that cast shadows (a point light's shadow is six renders of the scene). */
export const MAX_SHADOW_LIGHTS = 4;

/** What a mesh entry is built from: a shared unit geometry, the parse of a mesh's OBJ, or a glTF model's box. */
export type MeshBuild = 'sphere' | 'box' | 'plane' | ParsedObj;

/** What a light entry is built from: its kind, whether it casts a shadow, and an area light's sides (`area2+shadow`). */
export type LightBuild = string;

export function meshBuild(m: MeshDescriptor): MeshBuild {
  return m.geometry === 'mesh' || m.geometry === 'gltf' ? m.mesh! : m.geometry;
}

/** The first {@link MAX_SHADOW_LIGHTS} lights of the scene cast shadows. */
export function castsShadow(l: LightDescriptor): boolean {
  return l.index < MAX_SHADOW_LIGHTS;
}

export function lightBuild(l: LightDescriptor): LightBuild {
  const kind = l.kind === 'area' && l.twoSided ? 'area2' : l.kind;
  return castsShadow(l) ? `${kind}+shadow` : kind;
}

/** One entry of the next picture, in the descriptor's order. */
export interface PlanStep<D> {
  key: string;
  next: D;
  /** 'update': the shown entry of this key changes in place; 'create': a new entry is built. */
  action: 'update' | 'create';
}

export interface Plan<D> {
  /** Every entry to show, in the descriptor's order. */
  steps: PlanStep<D>[];
  /**
   * Keys of shown entries that go, gone from the descriptor or replaced (a replaced one's key is
   * created again in `steps`): applied before the steps.
   */
  remove: string[];
}

/** An entry shown now, as the plan sees it: what it was built from. */
export interface Shown<B> {
  readonly build: B;
}

/**
 * The plan that turns what is shown (`shown`, by key) into `next`. Keys are the ids; an id met
 * again in `next` (which the editor's ids never are) gets `#2`, `#3`, … so each entry still has
 * one key. Builds are compared by identity.
 */
export function plan<D, B>(shown: ReadonlyMap<string, Shown<B>>, next: readonly D[], idOf: (d: D) => string, buildOf: (d: D) => B): Plan<D> {
  const seen = new Map<string, number>();
  const steps: PlanStep<D>[] = [];
  const remove: string[] = [];
  for (const d of next) {
    const id = idOf(d);
    const n = (seen.get(id) ?? 0) + 1;
    seen.set(id, n);
    const key = n === 1 ? id : `${id}#${n}`;
    const was = shown.get(key);
    const same = was !== undefined && was.build === buildOf(d);
    if (was && !same) remove.push(key);
    steps.push({ key, next: d, action: same ? 'update' : 'create' });
  }
  const kept = new Set(steps.map((s) => s.key));
  for (const key of shown.keys()) if (!kept.has(key)) remove.push(key);
  return { steps, remove };
}

export const planMeshes = (shown: ReadonlyMap<string, Shown<MeshBuild>>, next: readonly MeshDescriptor[]) => plan(shown, next, (m) => m.id, meshBuild);

export const planLights = (shown: ReadonlyMap<string, Shown<LightBuild>>, next: readonly LightDescriptor[]) => plan(shown, next, (l) => l.id, lightBuild);
