// Building the page from data: every text goes in as a text node (never as HTML), so that study
// names, descriptions and error texts cannot inject markup or scripts.

// el('td', {class: 'number', dataset: {pointer: '/a'}, onclick}, 'text', child, ...)
export function el(tag, attributes = {}, ...children) {
  const node = document.createElement(tag);
  for (const [name, value] of Object.entries(attributes)) {
    if (value === undefined || value === null || value === false) continue;
    if (name === 'dataset') Object.assign(node.dataset, value);
    else if (name.startsWith('on')) node.addEventListener(name.slice(2), value);
    else if (name === 'class') node.className = value;
    else node.setAttribute(name, value === true ? '' : String(value));
  }
  append(node, children);
  return node;
}

export function append(node, children) {
  for (const child of children.flat(Infinity)) {
    if (child === undefined || child === null || child === false) continue;
    node.append(child instanceof Node ? child : document.createTextNode(String(child)));
  }
  return node;
}

export function replaceChildren(node, ...children) {
  node.replaceChildren();
  return append(node, children);
}

export function formatNumber(value, digits = 3) {
  if (value === null || value === undefined || Number.isNaN(value)) return '–';
  if (typeof value !== 'number') return String(value);
  if (Number.isInteger(value) && Math.abs(value) < 1e6) return String(value);
  const magnitude = Math.abs(value);
  if (magnitude !== 0 && (magnitude < 1e-3 || magnitude >= 1e6)) return value.toExponential(digits - 1);
  return String(Number(value.toPrecision(digits)));
}

export function formatDuration(seconds) {
  if (seconds === null || seconds === undefined) return '–';
  if (seconds < 90) return `${Math.round(seconds)} s`;
  if (seconds < 5400) return `${Math.round(seconds / 60)} min`;
  return `${(seconds / 3600).toFixed(1)} h`;
}

export function formatTime(unixSeconds) {
  if (!unixSeconds) return '–';
  return new Date(unixSeconds * 1000).toLocaleString();
}

// A table from column definitions [{label, value: row => text|Node, numeric}].
export function table(columns, rows, attributes = {}) {
  const head = el('tr', {}, columns.map((column) => el('th', {}, column.label)));
  const body = rows.map((row) =>
    el('tr', {}, columns.map((column) =>
      el('td', { class: column.numeric ? 'number' : column.className }, column.value(row)))));
  return el('table', attributes, el('thead', {}, head), el('tbody', {}, body));
}

export function select(options, current, onchange, attributes = {}) {
  const node = el('select', { ...attributes, onchange: (event) => onchange(event.target.value) },
    options.map(([value, label]) => el('option', { value, selected: value === current }, label)));
  return node;
}
