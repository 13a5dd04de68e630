// The page's names of a study's axes, from the service's description of each (GET /api/studies/ID
// and GET /api/cases/ID: axes; schemas/openapi.json, AxisDescription): label, symbol for legends,
// unit and scale all come from the service's one table of case fields. An axis it does not
// describe is named by its pointer, without a unit, in linear scale.
import { unitText, withUnit } from './units.js';

// Quantities that can go along x instead of an axis: the grid point's mean of a result quantity
// (the `mean` of its MeanEstimate `field`), which varies along the named axis (each point of a
// curve is still one grid point). Not case fields, so named here.
export const kDerivedX = {
  energy_per_contact: { along: 'impact_speed', field: 'energy_per_contact',
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
