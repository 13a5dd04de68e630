// A result's outcome by what leaves the wall (docs/IMPACT.md section 5), its small-strain check and
// the energy groups that govern it (schemas/result.schema.json: /outcome, /validity, /dimensionless),
// every dimensional value in the case's units (units.js caseUnits: SI for a physical case).
import { el, formatNumber, table } from '../dom.js';

const yesNo = (value) => (value === true ? 'yes' : value === false ? 'no' : '–');

export function facts(entries, attributes = {}) {
  return el('dl', { class: 'facts', ...attributes }, entries.filter(([, value]) => value !== undefined)
    .map(([label, value]) => [el('dt', {}, label), el('dd', {}, value === null ? '–' : value)]));
}

// Thresholds of the classification that carry a unit (the others are fractions).
const kThresholdKinds = { quiet_window: 'time' };

function thresholdFacts(thresholds, units) {
  return Object.entries(thresholds || {}).map(([name, value]) => {
    const kind = kThresholdKinds[name];
    const label = `threshold ${name.replaceAll('_', ' ')}`;
    return [kind ? units.label(label, kind) : label, formatNumber(kind ? units.value(value, kind) : value, 4)];
  });
}

function reentrainedTable(fragments, units) {
  const column = (label, kind, field) => ({
    label: units.label(label, kind), value: (f) => formatNumber(units.value(f[field], kind), 4), numeric: true });
  return table([{ label: 'Primaries', value: (f) => f.primaries, numeric: true }, column('Mass', 'mass', 'mass'),
    column('Normal velocity', 'speed', 'normal_velocity'), column('Speed', 'speed', 'speed')],
  fragments, { id: 'reentrained-table' });
}

export function outcomeSection(outcome, units) {
  if (!outcome) return null;
  const restitution = outcome.restitution || {};
  const fragments = outcome.reentrained_fragments || [];
  return el('section', { class: 'panel', id: 'outcome' }, el('h2', {}, 'Outcome'),
    el('p', { class: `outcome-class ${outcome.class}`, id: 'outcome-class' }, outcome.class),
    el('p', { class: 'note' }, outcome.reason),
    facts([['fractured on the wall', yesNo(outcome.fractured_on_wall)],
      ['retained mass fraction', formatNumber(outcome.retained_mass_fraction, 4)],
      ['re-entrained mass fraction', formatNumber(outcome.reentrained_mass_fraction, 4)],
      ['damage ratio', formatNumber(outcome.damage_ratio, 4)],
      ['fragments', formatNumber(outcome.fragment_count)],
      ['largest fragment share', formatNumber(outcome.largest_fragment_share, 4)],
      ['largest re-entrained share', formatNumber(outcome.largest_reentrained_share, 4)],
      ['restitution normal', formatNumber(restitution.normal, 4)],
      ['restitution tangential', formatNumber(restitution.tangential, 4)],
      ...thresholdFacts(outcome.thresholds, units)],
    { id: 'outcome-facts' }),
    el('h3', {}, `Re-entrained fragments (${fragments.length})`),
    fragments.length === 0 ? el('p', { class: 'note' }, 'Nothing left the wall.') : reentrainedTable(fragments, units));
}

function strainRow(label, strain) {
  if (!strain) return [label, undefined];
  return [label,
    `overlap ${formatNumber(strain.overlap_ratio, 3)}, contact radius ${formatNumber(strain.contact_radius_ratio, 3)}`];
}

export function validitySection(validity) {
  if (!validity) return null;
  const within = validity.small_strain;
  return el('section', { class: 'panel', id: 'validity' }, el('h2', {}, 'Validity'),
    el('p', { class: within ? 'ok' : 'warning', id: 'validity-verdict' }, within
      ? 'Within the small-strain range of the contact laws.'
      : 'Outside the small-strain range of the contact laws (docs/MODEL.md 3.7): this result extrapolates the ' +
        'contact model.'),
    facts([['deepest overlap / primary radius', formatNumber(validity.deepest_overlap_ratio, 4)],
      ['largest contact radius / primary radius', formatNumber(validity.largest_contact_radius_ratio, 4)],
      strainRow('particle-particle', validity.pair), strainRow('with the wall', validity.wall),
      strainRow('limits', validity.limits),
      ['ratios are upper bounds', yesNo(validity.bound)]], { id: 'validity-facts' }));
}

// A rolling energy, or what its absence means: null when the case has no rolling resistance.
const orNoRolling = (value) => (value === null ? 'no rolling resistance' : formatNumber(value, 4));

// The groups, with the impact's speed and energies in the case's units: for a physical case the
// result's SI values (/si) beside the reduced speed.
export function energyGroupsSection(result, units) {
  const { dimensionless, energy } = result;
  if (!dimensionless) return null;
  const joules = result.si || {};
  const siEnergy = (label, value) => [units.label(label, 'energy'),
    value === undefined ? undefined : orNoRolling(value)];
  const physicalRows = units.physical ? [
    [units.reduced('impact speed', 'speed'), formatNumber(dimensionless.impact_speed, 4)],
    siEnergy('impact kinetic energy', joules.impact_kinetic_energy_J), siEnergy('breaking energy',
      joules.breaking_energy_J),
    siEnergy('rolling energy', joules.rolling_energy_J),
  ] : [siEnergy('impact kinetic energy', (energy || {}).impact_kinetic)];
  return el('section', { class: 'panel', id: 'energy-groups' }, el('h2', {}, 'Energy groups'),
    facts([['E_kin / (N_c E_break)', formatNumber(dimensionless.energy_per_contact, 4)],
      ['E_kin / E_roll', orNoRolling(dimensionless.energy_over_rolling)],
      ['N_c, initial contacts', formatNumber(dimensionless.initial_contacts)],
      ['N, primaries', formatNumber(dimensionless.primaries)],
      ['λ (eq 19)', formatNumber(dimensionless.lambda, 4)], ['κ (eq 6)', formatNumber(dimensionless.kappa, 4)],
      ['γ/k_n', formatNumber(dimensionless.gamma_over_kn, 4)],
      [units.label('impact speed', 'speed'), formatNumber(units.value(dimensionless.impact_speed, 'speed'), 4)],
      ...physicalRows],
    { id: 'energy-groups-facts' }));
}
