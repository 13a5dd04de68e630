// A searched axis (docs/ADAPTIVE.md) places its cases at many distinct values, most holding one
// or two results: per value, a probability is 0 or 1 with a Wilson interval spanning most of
// [0, 1], and one series or table row per value says nothing. Along such an axis the page pools
// each curve's grid points (one condition: the series axes' values, in the slice) into a few bins
// of about equal numbers of results, the same bins in the probability and fragment-size plots and
// the flagged-results table (docs/WEB.md, "A study with an adaptive search"). Pure functions.

// At most this many bins per condition: with the 40-120 results a search spends per group, bins of
// 7-20 results, whose Wilson intervals are about +-0.2-0.35 wide.
export const kSearchBins = 6;
// z of a two-sided 95 % interval.
const kZ95 = 1.959963984540054;
const kFlagFields = ['fractured_on_wall', 'small_strain_exceeded', 'small_strain_unchecked'];

// The 95 % Wilson score interval of `count` successes in `total` trials (Wilson 1927), as the
// service gives each grid point's (GET /api/studies/ID/grid); [0, 1] without trials.
export function wilsonInterval(count, total) {
  if (total <= 0) return [0, 1];
  const share = count / total;
  const z2 = kZ95 * kZ95;
  const denominator = 1 + z2 / total;
  const centre = (share + z2 / (2 * total)) / denominator;
  const half = (kZ95 / denominator) * Math.sqrt((share * (1 - share)) / total + z2 / (4 * total * total));
  return [Math.max(0, centre - half), Math.min(1, centre + half)];
}

// Splits `points` (each with `value`, the searched axis's value, and `results`, sorted by value)
// into at most `bins` runs of neighbouring values holding about equal numbers of results; a value
// is never split. [{from, to, results, points}].
export function equalCountBins(points, bins = kSearchBins) {
  const values = [...new Set(points.map((point) => point.value))];
  let left = Math.min(bins, values.length);
  let remaining = points.reduce((sum, point) => sum + point.results, 0);
  const found = [];
  let current = null;
  for (const [i, point] of points.entries()) {
    if (!current) current = { from: point.value, to: point.value, results: 0, points: [] };
    current.points.push(point);
    current.results += point.results;
    current.to = point.value;
    const nextValue = points[i + 1]?.value;
    const closes = nextValue === undefined ||
      (nextValue !== point.value && left > 1 && current.results >= remaining / left);
    if (closes) {
      remaining -= current.results;
      left -= 1;
      found.push(current);
      current = null;
    }
  }
  return found;
}

// The mean of `values` weighted by `weights`, in log where `log` (the axis's scale) and all are positive.
function weightedMean(values, weights, log) {
  const inLog = log && values.every((value) => value > 0);
  const total = weights.reduce((sum, weight) => sum + weight, 0);
  const mean = values.reduce((sum, value, i) => sum + weights[i] * (inLog ? Math.log(value) : value), 0) / total;
  return inLog ? Math.exp(mean) : mean;
}

// The row standing for a bin's grid points (flag counts and results summed), its searched axis's
// value the bin's range [from, to].
function pooledRow(bin, along) {
  const rows = bin.points.map((point) => point.row);
  const row = { grid_point: { ...rows[0].grid_point, [along]: [bin.from, bin.to] }, range: [bin.from, bin.to],
    finished: bin.results };
  for (const field of kFlagFields) row[field] = rows.reduce((sum, each) => sum + (each[field] || 0), 0);
  return row;
}

// The bins of one curve's points (series.js curvesAlong: {x, row}) along the searched axis `along`.
export function curveBins(curve, along) {
  const points = curve.points.filter((point) => point.row.finished > 0)
    .map((point) => ({ value: point.row.grid_point[along], results: point.row.finished, x: point.x, row: point.row }))
    .sort((a, b) => a.value - b.value);
  return equalCountBins(points).map((bin) => ({ ...bin, row: pooledRow(bin, along) }));
}

// Cases of a bin's grid points that ended with `outcome`.
const pooledCount = (bin, outcome) =>
  bin.points.reduce((sum, point) => sum + (point.row.outcomes[outcome]?.count || 0), 0);

// Probability curves pooled into bins: per bin the outcome's count over the bin's determined results
// (those the fitted curve and the search's estimate are made of: an undetermined case is left out of
// both, docs/ADAPTIVE.md), or over all its results for `undetermined` itself, with the Wilson
// interval of the pooled counts, at the results-weighted mean x (in log on a log axis); a bin whose
// results all ended undetermined has no probability (y null: no point).
export function pooledProbabilityCurves(curves, { outcome, along, xLog }) {
  return curves.map((curve) => ({ ...curve, style: 'points', points: curveBins(curve, along).map((bin) => {
    const count = pooledCount(bin, outcome);
    const trials = outcome === 'undetermined' ? bin.results : bin.results - pooledCount(bin, 'undetermined');
    const [lo, hi] = trials > 0 ? wilsonInterval(count, trials) : [null, null];
    const x = weightedMean(bin.points.map((point) => point.x), bin.points.map((point) => point.results), xLog);
    return { x, y: trials > 0 ? count / trials : null, lo, hi, count, trials, results: bin.results,
      range: [bin.from, bin.to], row: bin.row };
  }) }));
}

// "5–9.33" of a bin's values [from, to] ("5" where they are one), each written by `format`.
export const spanText = ([from, to], format) => (from === to ? format(from) : `${format(from)}–${format(to)}`);

// "v₀ 5–9.33 m/s" in the symbols of `names` (axis_names.js AxisNames).
export function rangeText(names, along, range, format) {
  return `${names.symbol(along)} ${names.valueText(along, spanText(range, format))}`;
}

// Fragment-size distributions of one condition pooled into its bins (`bins`: curveBins): per bin,
// fragments of each size per result over the bin's grid points (GET .../fragment-sizes).
export function pooledFragmentCurves(response, bins, { along, names, format }) {
  const inBin = (bin, value) => value >= bin.from && value <= bin.to;
  return bins.map((bin) => {
    const members = response.grid_points.filter((point) => point.results > 0 && inBin(bin, point.grid_point[along]));
    const results = members.reduce((sum, point) => sum + point.results, 0);
    const counts = new Map();
    for (const point of members)
      for (const [primaries, count] of point.sizes) counts.set(primaries, (counts.get(primaries) || 0) + count);
    return { key: JSON.stringify([bin.from, bin.to]), results,
      label: `${rangeText(names, along, [bin.from, bin.to], format)} (${results} results)`,
      points: [...counts].sort(([a], [b]) => a - b)
        .map(([primaries, count]) => ({ x: primaries, y: count / results })) };
  }).filter((curve) => curve.results > 0);
}
