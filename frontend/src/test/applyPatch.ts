/**
 * A JSON Patch (RFC 6902) applier for tests, written apart from the diff it checks: applies the
 * operations in order to a deep copy of the document and returns it (the document is not changed).
 * Throws when an operation does not apply, as the server refuses it.
 */
export interface AnyPatchOperation {
  op: string;
  path: string;
  from?: string;
  value?: unknown;
}

type Container = Record<string, unknown> | unknown[];

export function applyPatch(document: unknown, operations: AnyPatchOperation[]): unknown {
  let root: unknown = structuredClone(document);
  for (const operation of operations) {
    const tokens = parse(operation.path);
    if (operation.op === 'add') root = add(root, tokens, structuredClone(operation.value));
    else if (operation.op === 'remove') root = remove(root, tokens);
    else if (operation.op === 'replace') root = add(remove(root, tokens), tokens, structuredClone(operation.value));
    else if (operation.op === 'move' || operation.op === 'copy') {
      const from = parse(operation.from ?? '');
      const value = structuredClone(get(root, from));
      if (operation.op === 'move') root = remove(root, from);
      root = add(root, tokens, value);
    } else if (operation.op === 'test') {
      if (JSON.stringify(get(root, tokens)) !== JSON.stringify(operation.value)) throw new Error(`test failed at ${operation.path}`);
    } else throw new Error(`unknown op ${operation.op}`);
  }
  return root;
}

function parse(pointer: string): string[] {
  if (pointer === '') return [];
  if (!pointer.startsWith('/')) throw new Error(`bad pointer ${pointer}`);
  return pointer
    .slice(1)
    .split('/')
    .map((t) => t.replace(/~1/g, '/').replace(/~0/g, '~'));
}

function get(root: unknown, tokens: string[]): unknown {
  let node = root;
  for (const token of tokens) {
    if (Array.isArray(node)) node = node[index(token, node.length - 1)];
    else if (typeof node === 'object' && node !== null && token in node) node = (node as Record<string, unknown>)[token];
    else throw new Error(`no value at ${tokens.join('/')}`);
  }
  return node;
}

function parent(root: unknown, tokens: string[]): Container {
  const node = get(root, tokens.slice(0, -1));
  if (typeof node !== 'object' || node === null) throw new Error(`no container at ${tokens.join('/')}`);
  return node as Container;
}

function add(root: unknown, tokens: string[], value: unknown): unknown {
  if (tokens.length === 0) return value;
  const container = parent(root, tokens);
  const last = tokens[tokens.length - 1];
  if (Array.isArray(container)) container.splice(last === '-' ? container.length : index(last, container.length), 0, value);
  else container[last] = value;
  return root;
}

function remove(root: unknown, tokens: string[]): unknown {
  get(root, tokens);
  const container = parent(root, tokens);
  const last = tokens[tokens.length - 1];
  if (Array.isArray(container)) container.splice(index(last, container.length - 1), 1);
  else delete container[last];
  return root;
}

function index(token: string, max: number): number {
  if (!/^(0|[1-9][0-9]*)$/.test(token) || Number(token) > max) throw new Error(`bad index ${token}`);
  return Number(token);
}
