// A result's outcome by what leaves the wall (docs/IMPACT.md section 5), its small-strain check and
// the energy groups that govern it (schemas/result.schema.json: /outcome, /validity, /dimensionless).
import { el, formatNumber, table } from '../dom.js';

const yesNo = (value) => (value === true ? 'yes' : value === false ? 'no' : '–');

export function facts(entries, attributes = {}) {
  return el('dl', { class: 'facts', ...attributes }, entries.filter(([, value]) => value !== undefined)
    .map(([label, value]) => [el('dt', {}, label), el('dd', {}, value === null ? '–' : value)]));
}

export function outcomeSection(outcome) {
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
      ['restitution normal', formatNumber(restitution.normal, 4)], ['restitution tangential', formatNumber(restitution.tangential, 4)],
      ...Object.entries(outcome.thresholds || {}).map(([name, value]) => [`threshold ${name.replaceAll('_', ' ')}`, formatNumber(value, 4)])],
    { id: 'outcome-facts' }),
    el('h3', {}, `Re-entrained fragments (${fragments.length})`),
    fragments.length === 0 ? el('p', { class: 'note' }, 'Nothing left the wall.')
      : table([{ label: 'Primaries', value: (f) => f.primaries, numeric: true },
        { label: 'Mass', value: (f) => formatNumber(f.mass, 4), numeric: true },
        { label: 'Normal velocity (d/τ)', value: (f) => formatNumber(f.normal_velocity, 4), numeric: true },
        { label: 'Speed (d/τ)', value: (f) => formatNumber(f.speed, 4), numeric: true }], fragments, { id: 'reentrained-table' }));
}

function strainRow(label, strain) {
  return strain ? [label, `overlap ${formatNumber(strain.overlap_ratio, 3)}, contact radius ${formatNumber(strain.contact_radius_ratio, 3)}`]
    : [label, undefined];
}

export function validitySection(validity) {
  if (!validity) return null;
  const within = validity.small_strain;
  return el('section', { class: 'panel', id: 'validity' }, el('h2', {}, 'Validity'),
    el('p', { class: within ? 'ok' : 'warning', id: 'validity-verdict' }, within
      ? 'Within the small-strain range of the contact laws.'
      : 'Outside the small-strain range of the contact laws (docs/MODEL.md 3.7): this result extrapolates the contact model.'),
    facts([['deepest overlap / primary radius', formatNumber(validity.deepest_overlap_ratio, 4)],
      ['largest contact radius / primary radius', formatNumber(validity.largest_contact_radius_ratio, 4)],
      strainRow('particle-particle', validity.pair), strainRow('with the wall', validity.wall), strainRow('limits', validity.limits),
      ['ratios are upper bounds', yesNo(validity.bound)]], { id: 'validity-facts' }));
}

export function energyGroupsSection(dimensionless, si) {
  if (!dimensionless) return null;
  const joules = si || {};
  return el('section', { class: 'panel', id: 'energy-groups' }, el('h2', {}, 'Energy groups'),
    facts([['E_kin / (N_c E_break)', formatNumber(dimensionless.energy_per_contact, 4)],
      ['E_kin / E_roll', formatNumber(dimensionless.energy_over_rolling, 4)],
      ['N_c, initial contacts', formatNumber(dimensionless.initial_contacts)],
      ['N, primaries', formatNumber(dimensionless.primaries)],
      ['λ (eq 19)', formatNumber(dimensionless.lambda, 4)], ['κ (eq 6)', formatNumber(dimensionless.kappa, 4)],
      ['γ/k_n', formatNumber(dimensionless.gamma_over_kn, 4)], ['impact speed (d/τ)', formatNumber(dimensionless.impact_speed, 4)],
      ['impact kinetic energy (J)', joules.impact_kinetic_energy_J === undefined ? undefined : formatNumber(joules.impact_kinetic_energy_J, 4)],
      ['breaking energy (J)', joules.breaking_energy_J === undefined ? undefined : formatNumber(joules.breaking_energy_J, 4)],
      ['rolling energy (J)', joules.rolling_energy_J === undefined ? undefined : formatNumber(joules.rolling_energy_J, 4)]],
    { id: 'energy-groups-facts' }));
}
