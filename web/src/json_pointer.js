// JSON pointers (RFC 6901) into a document: read, write (making the objects on the way) and
// remove a value.
export const escapeToken = (token) => token.replaceAll('~', '~0').replaceAll('/', '~1');
const unescapeToken = (token) => token.replaceAll('~1', '/').replaceAll('~0', '~');
const tokens = (pointer) => (pointer ? pointer.split('/').slice(1).map(unescapeToken) : []);
const isObject = (value) => value !== null && typeof value === 'object';

// The value at `pointer`, or undefined when the document has none there.
export function getAt(document, pointer) {
  let node = document;
  for (const key of tokens(pointer)) {
    if (!isObject(node) || !(key in node)) return undefined;
    node = node[key];
  }
  return node;
}

export function setAt(document, pointer, value) {
  const keys = tokens(pointer);
  let node = document;
  for (const key of keys.slice(0, -1)) {
    if (!isObject(node[key])) node[key] = {};
    node = node[key];
  }
  node[keys[keys.length - 1]] = value;
}

export function removeAt(document, pointer) {
  const keys = tokens(pointer);
  const parent = getAt(document, keys.slice(0, -1).map((key) => `/${escapeToken(key)}`).join(''));
  if (isObject(parent)) delete parent[keys[keys.length - 1]];
}

// The longest prefix of `pointer` that names a value of the document ('' for the document).
export function nearestPresent(document, pointer) {
  let path = pointer;
  while (path && getAt(document, path) === undefined) path = path.slice(0, path.lastIndexOf('/'));
  return path;
}
