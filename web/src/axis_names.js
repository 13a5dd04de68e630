// The page's names of a study's axes, from the service's description of each (GET /api/studies/ID
// and GET /api/cases/ID: axes; schemas/openapi.json, AxisDescription): label, symbol for legends,
// unit and scale all come from the service's one table of case fields. An axis it does not
// describe is named by its pointer, without a unit, in linear scale.
import { unitText, withUnit } from './units.js';

// What the page does with an axis follows from the case field it sets, not from how the study
// names it (a study may write the alias impact_speed or the pointer /impact/speed,
// docs/ORCHESTRATOR.md): an axis's identity is the service's alias of its field, or its pointer
// where the field has none. By identity, the roles:
//   speed   the default x, the dose of the fits, the critical speed's axis;
//   size    one curve per value, x of the critical speed against N, the shade of a colour;
//   series  one curve per value.
const kRoles = { impact_speed: 'speed', primaries: 'size', gamma_over_kn: 'series' };
// Roles whose axis gets one curve per value (the others are fixed by the slice choosers).
export const kSeriesRoles = ['size', 'series'];

// Quantities that can go along x instead of an axis: the grid point's mean of a result quantity
// (the `mean` of its MeanEstimate `field`), which varies along the axis of a role (each point of a
// curve is still one grid point). Not case fields, so named here.
export const kDerivedX = {
  energy_per_contact: { along: 'speed', field: 'energy_per_contact',
    label: 'energy per contact E_kin / (N_c E_break)', symbol: 'E/(N_c E_b)', unit: null, log_scale: true },
};

const undescribed = (name) => ({ name, label: name, symbol: name, unit: null, log_scale: false });

export class AxisNames {
  // `described`: the service's axes (StudyAxis or AxisDescription items).
  constructor(described = []) {
    this.byName = new Map(described.map((axis) => [axis.name, axis]));
  }

  describe(name) {
    return this.byName.get(name) || kDerivedX[name] || undescribed(name);
  }

  // The axis's identity: its alias ("impact_speed"), else its pointer, else its name.
  identity(name) {
    const axis = this.byName.get(name);
    return axis ? axis.alias || axis.pointer || name : name;
  }

  // 'speed', 'size', 'series' or null (kRoles).
  role(name) {
    return kRoles[this.identity(name)] || null;
  }

  // The study's name of the axis that `reference` names by the study's name, alias or pointer
  // (an address written for another study, or before the study named it so); null: none.
  find(reference) {
    if (this.byName.has(reference)) return reference;
    for (const [name, axis] of this.byName) if (axis.alias === reference || axis.pointer === reference) return name;
    return null;
  }

  // Whether the axis is the adaptive search's (docs/ADAPTIVE.md): its values are placed as the search
  // runs, not chosen by the study (the service's `role`, 'search' or 'grid').
  searched(name) {
    return this.byName.get(name)?.role === 'search';
  }

  // The study's name of its axis with `role` ('speed'); null: none.
  withRole(role) {
    for (const name of this.byName.keys()) if (this.role(name) === role) return name;
    return null;
  }

  // "impact speed v₀ (m/s)": the label with its unit, if it has one.
  label(name) {
    const axis = this.describe(name);
    return withUnit(axis.label, axis.unit);
  }

  // "v₀", for legends and curve names.
  symbol(name) {
    return this.describe(name).symbol;
  }

  unit(name) {
    return this.describe(name).unit;
  }

  logScale(name) {
    return this.describe(name).log_scale;
  }

  // A value of the axis with its unit, e.g. "20 m/s".
  valueText(name, value) {
    const unit = this.unit(name);
    return unit ? `${value} ${unitText(unit)}` : String(value);
  }
}
