// What the correlations and export services add to a study page, where they exist: fitted curves
// (one more dashed series per curve), critical speeds v10/v50/v90 with their intervals (one more
// series against N) and lookup-table downloads. Each is optional: an endpoint that answers 404
// hides its part. The shape read here is documented in docs/WEB.md.
import { getOptionalJson } from './api.js';
import { valueKey } from './series.js';

const kTableFormats = ['csv', 'dat', 'json', 'hdf5', 'melcor'];
const kCurvePoints = 25;
const kLevels = { 0.1: 'v10', 0.5: 'v50', 0.9: 'v90' };

const logistic = (eta) => 1 / (1 + Math.exp(-eta));

// A per-group fit of P in log impact speed from the correlations summary (docs/CORRELATIONS.md):
// its curve P(v) = logistic(b0 + b1 ln v) over its validity box, and its critical speeds.
function speedFitItem(fit) {
  const [b0, b1] = fit.coefficients;
  const { min, max } = fit.validity.impact_speed;
  const curve = Array.from({ length: kCurvePoints }, (_, i) => {
    const speed = min * (max / min) ** (i / (kCurvePoints - 1));
    return [speed, logistic(b0 + b1 * Math.log(speed))];
  });
  const criticalSpeeds = Object.fromEntries(fit.critical.filter((value) => kLevels[value.level])
    .map((value) => [kLevels[value.level], { value: value.estimate, ci95: value.ci95 }]));
  return { name: fit.name, outcome: fit.response, group: fit.group, status: fit.status, curve, critical_speeds: criticalSpeeds };
}

// The study's fitted speed curves, one item per group and outcome; null without the service.
export async function loadCorrelations(studyId) {
  const body = await getOptionalJson(`/api/studies/${studyId}/correlations`);
  if (!body) return null;
  return (body.fits || []).filter((fit) => fit.kind === 'logistic' && fit.dose === 'impact_speed' &&
    Object.keys(fit.group || {}).length > 0 && (fit.coefficients || []).length === 2 && fit.validity?.impact_speed)
    .map(speedFitItem);
}

// The fitted probability curves for `outcome`, keyed like the measured curves (series.js).
export function fittedCurves(correlations, outcome, measured) {
  if (!correlations) return [];
  const wanted = new Map(measured.map((curve) => [valueKey(curve.groupValues), curve]));
  return correlations
    .filter((item) => item.outcome === outcome && Array.isArray(item.curve))
    .map((item) => ({ item, curve: wanted.get(valueKey(item.group || {})) }))
    .filter(({ curve }) => curve)
    .map(({ item, curve }) => ({
      label: `${curve.label} (fit)`, color: curve.color, dashed: true,
      points: item.curve.map(([x, y]) => ({ x, y })),
    }));
}

// Fitted critical speeds against N, one series per level (v10, v50, v90) and group.
export function fittedCriticalCurves(correlations, outcome) {
  if (!correlations) return [];
  const series = new Map();
  for (const item of correlations) {
    if (item.outcome !== outcome || !item.critical_speeds || !item.group || !('primaries' in item.group)) continue;
    const { primaries, ...rest } = item.group;
    for (const [level, estimate] of Object.entries(item.critical_speeds)) {
      if (!estimate || typeof estimate.value !== 'number') continue;
      const key = `${level} ${valueKey(rest)}`;
      if (!series.has(key)) series.set(key, { label: `fitted ${level} ${Object.values(rest).join(', ')}`.trim(), points: [] });
      const [lo, hi] = estimate.ci95 || [null, null];
      series.get(key).points.push({ x: primaries, y: estimate.value, lo, hi });
    }
  }
  return [...series.values()].map((curve) => ({ ...curve, points: curve.points.sort((a, b) => a.x - b.x) }));
}

// The lookup-table formats the export service offers for the study; [] when it has none.
export async function tableFormats(studyId) {
  const response = await fetch(`/api/studies/${studyId}/tables?format=${kTableFormats[0]}`, { method: 'HEAD' });
  return response.status === 404 ? [] : kTableFormats;
}
