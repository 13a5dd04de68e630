// What an adaptive search found (GET /api/studies/ID/search, docs/ADAPTIVE.md): per group of the
// search, its current crossing of each target response and level (v50 of break-up, say) with the
// 95 % profile-likelihood interval of its Firth fit, drawn on the probability plot as a ring at
// (estimate, level) with the interval as a horizontal bar, in the colour of the group's curve, and
// listed beneath the plot.
import { getJsonOrNull } from './api.js';
import { doseOf, levelName } from './correlations.js';
import { formatNumber } from './dom.js';
import { valueKey } from './series.js';

// The search's groups; null for a study without a search.
export const loadSearch = (studyId) => getJsonOrNull(`/api/studies/${studyId}/search`);

const groupMatches = (group, gridPoint) => Object.entries(group)
  .every(([axis, value]) => valueKey(gridPoint[axis]) === valueKey(value));

const intervalText = (lower, upper) => `[${lower === null ? 'not bounded' : formatNumber(lower, 3)}, ` +
  `${upper === null ? 'not bounded' : formatNumber(upper, 3)}]`;

// "v50 = 14.4 m/s [9.83, 17.5]" of one estimate along `along`.
function estimateText(estimate, along, names) {
  const name = levelName(estimate.level, doseOf(along, names));
  return `${name} = ${names.valueText(along, formatNumber(estimate.estimate, 3))} ` +
    `${intervalText(estimate.lower, estimate.upper)}`;
}

// The search's crossings of `outcome` as curves of style 'crossing' ({x: estimate, y: level, xlo,
// xhi}), one per measured curve (its condition) that a search group matches; the curve's colour and
// legend group are the measured curve's. `state` and `cases` of the group go with each.
export function searchCrossings(search, measured, { outcome, along, names }) {
  if (!search) return [];
  const found = [];
  for (const curve of measured) {
    const gridPoint = curve.points[0]?.row.grid_point || {};
    const group = search.groups.find((each) => groupMatches(each.group, gridPoint));
    const estimates = (group?.estimates || [])
      .filter((estimate) => estimate.response === outcome && typeof estimate.estimate === 'number');
    if (estimates.length === 0) continue;
    const where = curve.groupLabel === 'all' ? '' : `, ${curve.groupLabel}`;
    found.push({ label: `search: ${estimates.map((each) => estimateText(each, along, names)).join(', ')}${where}`,
      style: 'crossing', color: curve.color, group: curve.group, groupLabel: curve.groupLabel,
      styleLabel: 'the search\'s estimate, bar: its 95 % interval', state: group.state, cases: group.cases,
      points: estimates.map((each) => ({ x: each.estimate, y: each.level, xlo: each.lower, xhi: each.upper })) });
  }
  return found;
}
