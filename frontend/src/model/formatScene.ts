/**
 * A scene as readable JSON: two-space indentation, but arrays of plain values (vectors such as
 * `[0, 1, 0]`) kept on one line, as the files in `scenes/` are written.
 */
export function formatScene(scene: unknown): string {
  return JSON.stringify(scene, null, 2).replace(/\[\s*([^[\]{}]*?)\s*\]/g, (_match, items: string) =>
    `[${items.split(/,\s*/).join(', ')}]`,
  );
}
