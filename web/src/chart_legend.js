// A chart's legend: one entry per curve, its swatch drawn as the curve is (a line with a dot for a
// measured series, a dot alone for measured points, a dashed or dotted line over a light band for
// a fitted one, a ring for markers). A click on an entry (or Enter) hides or shows its series.
import { el } from './dom.js';

function swatch(curve) {
  const intervals = curve.points.some((point) => typeof point.lo === 'number' && typeof point.hi === 'number');
  const extra = intervals && (curve.style === 'fitted' ? 'band' : 'whiskers');
  const node = el('span', { class: ['swatch', curve.style, curve.dash, extra].filter(Boolean).join(' ') });
  node.style.setProperty('--color', curve.color);
  return node;
}

// `toggle(curve, shown)` hides or shows the curve's series in the chart.
export function legend(curves, toggle) {
  return el('ul', { class: 'legend' }, curves.map((curve) => {
    const entry = el('li', { tabindex: 0, role: 'switch', 'aria-checked': 'true', title: 'click to hide or show',
      dataset: { points: curve.points.length, style: curve.style } }, swatch(curve), curve.label);
    const flip = () => {
      const shown = entry.getAttribute('aria-checked') !== 'true';
      entry.setAttribute('aria-checked', String(shown));
      entry.classList.toggle('off', !shown);
      toggle(curve, shown);
    };
    entry.addEventListener('click', flip);
    entry.addEventListener('keydown', (event) => {
      if (event.key === 'Enter' || event.key === ' ') {
        event.preventDefault();
        flip();
      }
    });
    return entry;
  }));
}
