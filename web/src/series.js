// Shaping the server's per-grid-point statistics into plot series: pure functions, no DOM.
import { unitText, withUnit } from './units.js';

const kAxisLabels = {
  impact_speed: 'impact speed v₀', gamma_over_kn: 'γ/k_n', primaries: 'N',
  energy_per_contact: 'energy per contact E_kin / (N_c E_break)',
};
// The kind of unit of each axis that has one (the study's units name it: study.units).
const kAxisUnits = { impact_speed: 'speed' };
const kShortLabels = { impact_speed: 'v₀', gamma_over_kn: 'γ/k_n', primaries: 'N', energy_per_contact: 'E/(N_c E_b)' };
// Axes that get one curve per value (the others are fixed by the slice choosers).
export const kSeriesAxes = ['primaries', 'gamma_over_kn'];
// Quantities that can go along x instead of an axis: the grid point's mean of a result quantity
// (the `mean` of its MeanEstimate), which varies along the named axis (each point of a curve is
// still one grid point).
const kDerivedX = { energy_per_contact: { along: 'impact_speed', field: 'energy_per_contact' } };

// An axis's name for the page, with its unit in the study's `units` (GET /api/studies/ID) if it has one.
export const axisLabel = (name, units = {}) => withUnit(kAxisLabels[name] || name, units[kAxisUnits[name]]);
// A value of an axis with its unit, e.g. "20 m/s".
export const axisValueText = (name, value, units = {}) => {
  const unit = units[kAxisUnits[name]];
  return unit ? `${value} ${unitText(unit)}` : String(value);
};
export const shortAxisLabel = (name) => kShortLabels[name] || name;
const shortLabel = shortAxisLabel;
export const valueKey = (value) => JSON.stringify(value);
// The same key for the same axis values in whatever order: a condition of the series axes.
export const conditionKey = (values) => JSON.stringify(Object.entries(values)
  .sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0)));

// The axis a choice of x runs along: itself, or the axis a derived quantity varies with.
export const alongAxis = (xAxis) => (kDerivedX[xAxis] ? kDerivedX[xAxis].along : xAxis);
export const xValueOf = (xAxis) => (kDerivedX[xAxis]
  ? (row) => row[kDerivedX[xAxis].field]?.mean ?? null : (row) => row.grid_point[xAxis]);

// The derived quantities the grid offers along x: those whose axis is swept and that some grid
// point has a value of.
export function derivedXChoices(grid) {
  return Object.entries(kDerivedX)
    .filter(([, { along, field }]) => grid.axes.some((axis) => axis.name === along && axis.values.length > 1) &&
      grid.grid_points.some((row) => typeof row[field]?.mean === 'number'))
    .map(([name]) => name);
}

// The axis along x: impact_speed when swept, else the first numeric axis with several values.
export function defaultXAxis(axes) {
  const swept = axes.filter((axis) => axis.values.length > 1 && axis.values.every((v) => typeof v === 'number'));
  const speed = swept.find((axis) => axis.name === 'impact_speed');
  return (speed || swept[0] || {}).name || null;
}

// Axes with several values other than x and the series axes: each fixed to one value.
export function sliceAxes(axes, xAxis) {
  const along = alongAxis(xAxis);
  return axes.filter((axis) => axis.values.length > 1 && axis.name !== along && !kSeriesAxes.includes(axis.name));
}

export function inSlice(gridPoint, slice) {
  return Object.entries(slice).every(([axis, key]) => valueKey(gridPoint[axis]) === key);
}

function curveLabel(groupValues) {
  const parts = Object.entries(groupValues).map(([axis, value]) => `${shortLabel(axis)} = ${value}`);
  return parts.length ? parts.join(', ') : 'all';
}

// One curve per combination of the series axes, among the grid points in the slice: points
// {x, y, lo, hi} sorted by x, from yOf(row) = {y, lo, hi} or null (no value there).
export function curvesAlong(rows, { axes, xAxis, slice, yOf }) {
  const along = alongAxis(xAxis);
  const xOf = xValueOf(xAxis);
  const seriesAxes = axes.filter((axis) => kSeriesAxes.includes(axis.name) && axis.name !== along && axis.values.length > 1);
  const curves = new Map();
  for (const row of rows) {
    if (!inSlice(row.grid_point, slice)) continue;
    const value = yOf(row);
    const x = xOf(row);
    if (!value || value.y === null || value.y === undefined || x === null) continue;
    const groupValues = Object.fromEntries(seriesAxes.map((axis) => [axis.name, row.grid_point[axis.name]]));
    const key = valueKey(groupValues);
    if (!curves.has(key)) curves.set(key, { key, groupValues, label: curveLabel(groupValues), points: [] });
    curves.get(key).points.push({ x, ...value, row });
  }
  const sorted = [...curves.values()];
  for (const curve of sorted) curve.points.sort((a, b) => a.x - b.x);
  return sorted;
}

// Probability of `outcome` with its 95 % Wilson interval (the server's numbers).
export const probabilityOf = (outcome) => (row) => {
  const estimate = row.outcomes[outcome];
  if (!estimate || estimate.probability === null) return null;
  return { y: estimate.probability, lo: estimate.ci95[0], hi: estimate.ci95[1] };
};

// A mean with its 95 % Student interval (the server's numbers).
export const meanOf = (quantity) => (row) => {
  const estimate = row[quantity];
  if (!estimate) return null;
  return { y: estimate.mean, lo: estimate.ci95 ? estimate.ci95[0] : null, hi: estimate.ci95 ? estimate.ci95[1] : null };
};

// Critical speed against N from the service's measured crossings (`observed_crossings` of each
// group's fit, which the fitting library computes): one series per value of the series axes other
// than N (those outside the slice).
export function observedCriticalCurves(fits, slice, level = 0.5) {
  const series = new Map();
  for (const fit of fits) {
    const crossing = (fit.observed_crossings || []).find((c) => c.level === level);
    if (!('primaries' in fit.group) || !crossing || typeof crossing.dose !== 'number') continue;
    const rest = Object.fromEntries(Object.entries(fit.group).filter(([axis]) => axis !== 'primaries' && !(axis in slice)));
    const key = valueKey(rest);
    if (!series.has(key)) series.set(key, { key, groupValues: rest, label: curveLabel(rest), points: [] });
    series.get(key).points.push({ x: fit.group.primaries, y: crossing.dose });
  }
  const sorted = [...series.values()];
  for (const curve of sorted) curve.points.sort((a, b) => a.x - b.x);
  return sorted;
}

// Fragment-size distributions: one series per x value (e.g. impact speed), fragments of each size
// per result.
export function fragmentCurves(response, xAxis, units) {
  const along = alongAxis(xAxis);
  return response.grid_points
    .filter((point) => point.results > 0)
    .sort((a, b) => a.grid_point[along] - b.grid_point[along])
    .map((point) => ({
      key: valueKey(point.grid_point[along]),
      label: `${shortLabel(along)} = ${axisValueText(along, point.grid_point[along], units)} ` +
        `(${point.results} results)`,
      points: point.sizes.map(([primaries, count]) => ({ x: primaries, y: count / point.results })),
    }));
}

// Grid points of the curves whose results carry a flag (e.g. small_strain_exceeded): one series of
// markers at the curves' points, labelled with the number of flagged results.
export function flaggedPoints(curves, flag, label) {
  const points = curves.flatMap((curve) => curve.points.filter((point) => point.row[flag] > 0));
  const results = points.reduce((sum, point) => sum + point.row[flag], 0);
  return { label: `${label} (${results} results at ${points.length} grid points)`, style: 'markers',
    color: '#b3261e', points: points.map(({ x, y, row }) => ({ x, y, count: row[flag] })) };
}
