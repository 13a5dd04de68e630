// The study's flagged results (docs/IMPACT.md section 5): deposits fractured on the wall, results
// outside the contact laws' small-strain range and results without that check; counted over the
// study and listed per grid point of the plotted slice.
import { el, formatNumber, replaceChildren, table } from '../dom.js';
import { inSlice } from '../series.js';
import { spanText } from '../search_bins.js';

const kMaxRows = 50;
export const kFlags = [
  ['fractured_on_wall', 'fractured on the wall'],
  ['small_strain_exceeded', 'outside the small-strain range'],
  ['small_strain_unchecked', 'small strain not checked'],
];

// An axis value, or a bin's range of them, in 4 digits (the fragment plot's bin labels too).
export const fourDigits = (value) => formatNumber(value, 4);
const valueText = (value) => (Array.isArray(value) ? spanText(value, fourDigits) : fourDigits(value));

const total = (rows, field) => rows.reduce((sum, row) => sum + (row[field] || 0), 0);

export function createFlags() {
  const summary = el('p', { id: 'flags-summary' });
  const holder = el('div', { id: 'flags-table' });
  const node = el('section', { class: 'panel', id: 'panel-flags' },
    el('h2', {}, 'Flagged results'), summary, holder,
    el('p', { class: 'note' }, 'Fractured on the wall: more than one fragment rests on the wall (a stick that ' +
      'cracked in place is still a stick). Outside the small-strain range: the deepest overlap or the largest ' +
      'contact radius left the range of the contact laws (docs/MODEL.md 3.7), so that the result extrapolates the ' +
      'contact model. Not checked: results stored before the check existed.'));

  // `shownAxes`: the axes that vary within the slice (x and the series axes), one column each.
  // `pooled`: along a searched axis, the rows of its bins (search_bins.js curveBins), each axis
  // value of which is one value or a range [from, to]; null: one row per grid point.
  function draw(grid, { slice, shownAxes, names, pooled = null }) {
    const counts = kFlags.map(([flag, label]) => `${total(grid.grid_points, flag)} ${label}`);
    replaceChildren(summary, `Of ${total(grid.grid_points, 'finished')} results: ${counts.join(', ')}.`);
    for (const [flag] of kFlags) summary.dataset[flag] = total(grid.grid_points, flag);
    const rows = (pooled || grid.grid_points.filter((row) => inSlice(row.grid_point, slice)))
      .filter((row) => kFlags.some(([flag]) => row[flag] > 0));
    holder.dataset.rows = rows.length;
    holder.dataset.pooled = Boolean(pooled);
    const columns = [
      ...shownAxes.map((axis) => ({ label: names.label(axis), value: (row) => valueText(row.grid_point[axis]),
        numeric: true })),
      { label: 'results', value: (row) => row.finished, numeric: true },
      ...kFlags.map(([flag, label]) => ({ label, value: (row) => row[flag], numeric: true })),
    ];
    replaceChildren(holder, rows.length === 0
      ? el('p', { class: 'note' }, 'No flagged result among the plotted grid points.')
      : [table(columns, rows.slice(0, kMaxRows)),
        rows.length > kMaxRows && el('p', { class: 'note' }, `and ${rows.length - kMaxRows} more grid points`),
        pooled && el('p', { class: 'note' }, 'Along the searched axis, one row per bin of the probability plot.')]);
  }
  return { node, draw };
}
