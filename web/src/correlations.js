// What the correlations service (docs/CORRELATIONS.md) adds to a study page: the per-group logistic
// fits of an outcome against the impact speed or the energy per contact, drawn as dashed curves with
// their 95 % bands over the measured points; the fitted critical speeds v10, v50, v90 against N with
// their profile-likelihood intervals; a table of them, marking the values the data do not pin down
// (extrapolations), and the scaling exponents of v50. The summary
// (GET /api/studies/ID/correlations) names every fit with its group and critical values; a fit's
// curve comes from its own document (GET .../correlations/NAME), fetched once per fit. A 404 (the study
// has no results yet) hides these parts.
import { getJson, getJsonOrNull } from './api.js';
import { conditionKey, observedCriticalCurves, valueKey } from './series.js';

// The dose of the fits along x (series.js): the impact speed along the axis with the role of the
// speed, whatever the study calls it (axis_names.js AxisNames `names`), the energy per contact along
// that; null along any other axis.
export function doseOf(xAxis, names) {
  if (names.role(xAxis) === 'speed') return 'impact_speed';
  return xAxis === 'energy_per_contact' ? 'energy_per_contact' : null;
}
// The levels whose crossings are the critical values, and how each is drawn against N.
export const kLevels = [0.1, 0.5, 0.9];
const kLevelDashes = { 0.1: 'dashed', 0.5: 'solid', 0.9: 'dotted' };
const kDosePrefixes = { impact_speed: 'v', energy_per_contact: 'E' };
// A critical value's name: v50 for the speed where P crosses 0.5, E50 for the energy per contact.
export const levelName = (level, dose) => `${kDosePrefixes[dose] || 'x'}${Math.round(level * 100)}`;

export const loadCorrelationSummary = (studyId) => getJsonOrNull(`/api/studies/${studyId}/correlations`);

// Whether every axis value of a fit's group equals the grid point's.
const groupMatches = (group, gridPoint) => Object.entries(group)
  .every(([axis, value]) => valueKey(gridPoint[axis]) === valueKey(value));
// Whether the group lies in the slice ({axis: valueKey}) the plots show.
const inSlice = (group, slice) => Object.entries(slice)
  .every(([axis, key]) => !(axis in group) || valueKey(group[axis]) === key);
// A group's own fit: a pooled model names the axes it pools along.
const isGroupFit = (fit, outcome, dose) => fit.kind === 'logistic' && fit.response === outcome && fit.dose === dose &&
  fit.pooled_over.length === 0;

export class Correlations {
  constructor(studyId, summary) {
    this.studyId = studyId;
    this.summary = summary;
    this.documents = new Map();
  }

  document(name) {
    if (!this.documents.has(name))
      this.documents.set(name, getJson(`/api/studies/${this.studyId}/correlations/${encodeURIComponent(name)}`));
    return this.documents.get(name);
  }

  // The per-group fits of `outcome` against the dose of `xAxis` in `slice`; [] when x has no fits.
  groupFits(outcome, xAxis, slice, names) {
    const dose = doseOf(xAxis, names);
    if (!dose) return [];
    return this.summary.fits.filter((fit) => isGroupFit(fit, outcome, dose) && inSlice(fit.group, slice));
  }

  // One dashed curve with its band per measured curve (series.js curvesAlong) that has a fit.
  async fittedCurves(measured, { outcome, xAxis, slice, names }) {
    const fits = this.groupFits(outcome, xAxis, slice, names);
    const pairs = measured
      .map((curve) => ({ curve, fit: fits.find((fit) => groupMatches(fit.group, curve.points[0].row.grid_point)) }))
      .filter(({ fit }) => fit);
    const documents = await Promise.all(pairs.map(({ fit }) => this.document(fit.name)));
    return pairs.flatMap(({ curve, fit }, i) => (documents[i].curves || []).slice(0, 1).map((fitted) => ({
      label: `${curve.label} (fit)`, color: curve.color, style: 'fitted', fit: fit.name,
      group: curve.group, groupLabel: curve.groupLabel, styleLabel: 'fit, band: 95 % interval',
      points: fitted.points.map((point) => ({ x: point.dose, y: point.value, lo: point.ci95[0], hi: point.ci95[1] })),
    })));
  }

  // Fitted critical values against N: per level and per condition (the values of the group's axes
  // other than N outside the slice), the groups' estimates; v50 carries its 95 % interval as a
  // band and is drawn solid, v10 dashed, v90 dotted. `group` keys the condition (its axis values
  // in `groupValues`), so that a condition's measured and fitted series share a colour and an
  // entry of the legend. Axes named in `names` (axis_names.js AxisNames).
  criticalCurves(outcome, xAxis, slice, names) {
    const size = names.withRole('size');
    const series = new Map();
    for (const fit of this.groupFits(outcome, xAxis, slice, names)) {
      if (!size || !(size in fit.group)) continue;
      const others = Object.entries(fit.group).filter(([axis]) => axis !== size && !(axis in slice));
      for (const critical of fit.critical || []) {
        if (typeof critical.estimate !== 'number') continue;
        const level = levelName(critical.level, fit.dose);
        const key = `${level} ${valueKey(others)}`;
        const where = others.map(([axis, value]) => `, ${names.symbol(axis)} = ${value}`);
        const groupValues = Object.fromEntries(others);
        if (!series.has(key)) series.set(key, { label: `fitted ${level}${where.join('')}`, level, style: 'fitted',
          groupValues, group: conditionKey(groupValues), groupLabel: where.join('').slice(2) || 'all',
          styleLabel: `fitted ${level}${critical.level === 0.5 ? ', band: 95 % interval' : ''}`,
          dash: kLevelDashes[critical.level], points: [] });
        const [lo, hi] = critical.level === 0.5 && critical.ci95 ? critical.ci95 : [null, null];
        series.get(key).points.push({ x: fit.group[size], y: critical.estimate, lo, hi });
      }
    }
    return [...series.values()].map((curve) => ({ ...curve, points: curve.points.sort((a, b) => a.x - b.x) }));
  }

  // The measured crossings of 0.5 against N, as the service computes them from each group's
  // measured proportions (observed_crossings of the fits along x), one series per other series axis.
  observedCurves(outcome, xAxis, slice, names) {
    return observedCriticalCurves(this.groupFits(outcome, xAxis, slice, names), slice, names);
  }

  // The scaling fits of v50 for `outcome` (exponents per axis) whose group lies in the slice.
  scalings(outcome, slice) {
    return this.summary.fits.filter((fit) => fit.kind === 'scaling' && fit.response === outcome && fit.level === 0.5 &&
      inSlice(fit.group || {}, slice));
  }
}

// A critical value is an extrapolation when its estimate lies outside the doses its fit saw (the
// fit's validity box) or its 95 % interval reaches more than kFarBeyond times beyond them.
export const kFarBeyond = 1.5;

// The extrapolated critical values of `fits` ([{fit, level, critical, range: [min, max]}]).
export function extrapolations(fits) {
  const found = [];
  for (const fit of fits) {
    const box = (fit.validity || {})[fit.dose];
    if (!box) continue;
    for (const critical of fit.critical || []) {
      if (typeof critical.estimate !== 'number') continue;
      const [lo, hi] = critical.ci95 || [critical.estimate, critical.estimate];
      const outside = critical.estimate < box.min || critical.estimate > box.max;
      if (outside || lo < box.min / kFarBeyond || hi > box.max * kFarBeyond)
        found.push({ fit, level: levelName(critical.level, fit.dose), critical, range: [box.min, box.max] });
    }
  }
  return found;
}
