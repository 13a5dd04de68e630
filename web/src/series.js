// Shaping the server's per-grid-point statistics into plot series: pure functions, no DOM. Axes
// are keyed by the study's names for them (as grid_point and the fits' groups key them) and take
// their roles from `names` (axis_names.js AxisNames), by the field each sets.
import { kDerivedX, kSeriesRoles } from './axis_names.js';

// Whether the axis gets one curve per value (the others are fixed by the slice choosers).
const isSeriesAxis = (name, names) => kSeriesRoles.includes(names.role(name));
export const valueKey = (value) => JSON.stringify(value);
// The same key for the same axis values in whatever order: a condition of the series axes.
export const conditionKey = (values) => JSON.stringify(Object.entries(values)
  .sort(([a], [b]) => (a < b ? -1 : a > b ? 1 : 0)));

// The axis a choice of x runs along: itself, or the axis a derived quantity varies with.
export const alongAxis = (xAxis, names) => (kDerivedX[xAxis] ? names.withRole(kDerivedX[xAxis].along) : xAxis);
export const xValueOf = (xAxis) => (kDerivedX[xAxis]
  ? (row) => row[kDerivedX[xAxis].field]?.mean ?? null : (row) => row.grid_point[xAxis]);

// The derived quantities the grid offers along x: those whose axis is swept and that some grid
// point has a value of.
export function derivedXChoices(grid, names) {
  return Object.entries(kDerivedX)
    .filter(([name, { field }]) => grid.axes.some((axis) => axis.name === alongAxis(name, names) &&
      axis.values.length > 1) &&
      grid.grid_points.some((row) => typeof row[field]?.mean === 'number'))
    .map(([name]) => name);
}

// The axis along x: the impact speed when swept, else the first numeric axis with several values.
export function defaultXAxis(axes, names) {
  const swept = axes.filter((axis) => axis.values.length > 1 && axis.values.every((v) => typeof v === 'number'));
  const speed = swept.find((axis) => names.role(axis.name) === 'speed');
  return (speed || swept[0] || {}).name || null;
}

// Axes with several values other than x and the series axes: each fixed to one value.
export function sliceAxes(axes, xAxis, names) {
  const along = alongAxis(xAxis, names);
  return axes.filter((axis) => axis.values.length > 1 && axis.name !== along && !isSeriesAxis(axis.name, names));
}

export function inSlice(gridPoint, slice) {
  return Object.entries(slice).every(([axis, key]) => valueKey(gridPoint[axis]) === key);
}

// "N = 16, γ/k_n = 0.001" in the symbols of `names` (axis_names.js AxisNames).
function curveLabel(groupValues, names) {
  const parts = Object.entries(groupValues).map(([axis, value]) => `${names.symbol(axis)} = ${value}`);
  return parts.length ? parts.join(', ') : 'all';
}

// One curve per combination of the series axes, among the grid points in the slice: points
// {x, y, lo, hi} sorted by x, from yOf(row) = {y, lo, hi} or null (no value there), named in `names`.
export function curvesAlong(rows, { axes, xAxis, slice, yOf, names }) {
  const along = alongAxis(xAxis, names);
  const xOf = xValueOf(xAxis);
  const seriesAxes = axes.filter((axis) => isSeriesAxis(axis.name, names) && axis.name !== along &&
    axis.values.length > 1);
  const curves = new Map();
  for (const row of rows) {
    if (!inSlice(row.grid_point, slice)) continue;
    const value = yOf(row);
    const x = xOf(row);
    if (!value || value.y === null || value.y === undefined || x === null) continue;
    const groupValues = Object.fromEntries(seriesAxes.map((axis) => [axis.name, row.grid_point[axis.name]]));
    const key = valueKey(groupValues);
    if (!curves.has(key)) curves.set(key, { key, groupValues, label: curveLabel(groupValues, names),
      points: [] });
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

// A grid point's results (y: their number), whatever their outcomes: the points that bins and
// per-grid-point tables pool, including those whose results all ended undetermined (which have no
// probability of stick, bounce or break-up).
export const resultsIn = (row) => (row.finished > 0 ? { y: row.finished } : null);

// A mean with its 95 % Student interval (the server's numbers).
export const meanOf = (quantity) => (row) => {
  const estimate = row[quantity];
  if (!estimate) return null;
  return { y: estimate.mean, lo: estimate.ci95 ? estimate.ci95[0] : null, hi: estimate.ci95 ? estimate.ci95[1] : null };
};

// Critical speed against N from the service's measured crossings (`observed_crossings` of each
// group's fit, which the fitting library computes): one series per value of the series axes other
// than N (those outside the slice), named in `names`.
export function observedCriticalCurves(fits, slice, names, level = 0.5) {
  const size = names.withRole('size');
  const series = new Map();
  for (const fit of fits) {
    const crossing = (fit.observed_crossings || []).find((c) => c.level === level);
    if (!size || !(size in fit.group) || !crossing || typeof crossing.dose !== 'number') continue;
    const rest = Object.fromEntries(Object.entries(fit.group)
      .filter(([axis]) => axis !== size && !(axis in slice)));
    const key = valueKey(rest);
    if (!series.has(key)) series.set(key, { key, groupValues: rest, label: curveLabel(rest, names), points: [] });
    series.get(key).points.push({ x: fit.group[size], y: crossing.dose });
  }
  const sorted = [...series.values()];
  for (const curve of sorted) curve.points.sort((a, b) => a.x - b.x);
  return sorted;
}

// Fragment-size distributions: one series per x value (e.g. impact speed), fragments of each size
// per result, named in `names`.
export function fragmentCurves(response, xAxis, names) {
  const along = alongAxis(xAxis, names);
  return response.grid_points
    .filter((point) => point.results > 0)
    .sort((a, b) => a.grid_point[along] - b.grid_point[along])
    .map((point) => ({
      key: valueKey(point.grid_point[along]),
      label: `${names.symbol(along)} = ${names.valueText(along, point.grid_point[along])} ` +
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
