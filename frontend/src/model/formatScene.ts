/**
 * A scene as readable JSON: two-space indentation, but arrays of plain values (vectors such as
 * `[0, 1, 0]`) kept on one line, as the files in `scenes/` are written. Strings (a name, a mesh's
 * inline OBJ text) are copied as they are, brackets included.
 */
export function formatScene(scene: unknown): string {
  // A string literal (written unrolled, so a long one does not exhaust the regex stack), or an array without nesting.
  return JSON.stringify(scene, null, 2).replace(/"[^"\\]*(?:\\.[^"\\]*)*"|\[\s*([^[\]{}"]*?)\s*\]/g, (match, items: string | undefined) =>
    items === undefined ? match : `[${items.split(/,\s*/).join(', ')}]`,
  );
}
