import { describeField, plainMessage } from '../components/fieldWords';
import type { Scene } from '../model/types';

/** The field names and plain messages of a sent scene, for an error summary; none for JSON text. */
export function fieldWordsOf(scene: unknown): { describe?: (field: string) => string; plain?: (message: string) => string } {
  if (typeof scene !== 'object' || scene === null || !Array.isArray((scene as Scene).objects)) return {};
  const s = scene as Scene;
  return { describe: (field) => describeField(s, field), plain: (message) => plainMessage(s, message) };
}
