// A chart's legend. Curves that belong to groups (curve.group, e.g. one N and gamma/k_n, with its
// measured series and its fit) get a key of their kinds, each swatch drawn as the kind is plotted
// (a line with a dot and a whisker for measured values, a dot alone for measured points, a dashed,
// dotted or solid line over a light band for a fit, a ring for markers) and labelled by
// curve.styleLabel, then one entry per group in the group's colour (none for a single group).
// Other curves get an entry of their own, with their swatch. A click on an entry (or Enter) hides
// or shows its series: a kind in the key all of that kind, a group all of that group.
import { el } from './dom.js';

const kKeyColor = '#4a5361';

function swatch(curve, color = curve.color) {
  const intervals = curve.points.some((point) => typeof point.lo === 'number' && typeof point.hi === 'number');
  const extra = intervals && (curve.style === 'fitted' ? 'band' : 'whiskers');
  const node = el('span', { class: ['swatch', curve.style, curve.dash, extra].filter(Boolean).join(' ') });
  node.style.setProperty('--color', color);
  return node;
}

function colourBlock(color) {
  const node = el('span', { class: 'swatch group' });
  node.style.setProperty('--color', color);
  return node;
}

// A legend entry that flips between shown and hidden on a click or Enter, calling `onFlip(shown)`.
function switchEntry(children, dataset, onFlip) {
  const entry = el('li',
    { tabindex: 0, role: 'switch', 'aria-checked': 'true', title: 'click to hide or show', dataset }, children);
  const flip = () => {
    const shown = entry.getAttribute('aria-checked') !== 'true';
    entry.setAttribute('aria-checked', String(shown));
    entry.classList.toggle('off', !shown);
    onFlip(shown);
  };
  entry.addEventListener('click', flip);
  entry.addEventListener('keydown', (event) => {
    if (event.key === 'Enter' || event.key === ' ') {
      event.preventDefault();
      flip();
    }
  });
  return entry;
}

const kindOf = (curve) => `${curve.style} ${curve.dash || ''} ${curve.styleLabel}`;

// `toggle(curve, shown)` hides or shows the curve's series in the chart.
export function legend(curves, toggle) {
  const hidden = new Set();
  const shown = new Map(curves.map((curve) => [curve, true]));
  const update = () => curves.forEach((curve) => {
    const visible = !hidden.has(`kind:${kindOf(curve)}`) && !hidden.has(`group:${curve.group}`) && !hidden.has(curve);
    if (visible !== shown.get(curve)) toggle(curve, visible);
    shown.set(curve, visible);
  });
  const flipping = (key) => (on) => {
    if (on) hidden.delete(key);
    else hidden.add(key);
    update();
  };
  const grouped = curves.filter((curve) => curve.group !== undefined);
  const kinds = [...new Map(grouped.map((curve) => [kindOf(curve), curve])).values()];
  const groups = [...new Map(grouped.map((curve) => [curve.group, curve])).values()];
  // One group needs no entry of its own: the key shows its colour.
  const keyColor = groups.length === 1 ? groups[0].color : kKeyColor;
  const keyEntries = kinds.map((curve) => switchEntry([swatch(curve, keyColor), curve.styleLabel],
    { kind: curve.style, points: 0 }, flipping(`kind:${kindOf(curve)}`)));
  const pointsOf = (group) => grouped.filter((c) => c.group === group).reduce((n, c) => n + c.points.length, 0);
  const groupEntries = groups.length === 1 ? [] : groups.map((curve) =>
    switchEntry([colourBlock(curve.color), curve.groupLabel], { group: curve.group, points: pointsOf(curve.group) },
      flipping(`group:${curve.group}`)));
  const ownEntries = curves.filter((curve) => curve.group === undefined).map((curve) =>
    switchEntry([swatch(curve), curve.label], { style: curve.style, points: curve.points.length }, flipping(curve)));
  return el('div', { class: 'legends' },
    keyEntries.length > 0 && el('ul', { class: 'legend key' }, keyEntries),
    el('ul', { class: 'legend' }, groupEntries, ownEntries));
}
