// The units of a study's or a case's numbers, as the API names them (schemas/openapi.json, Units:
// SI for physical studies; d, m, tau = sqrt(m/k_n) and k_n d^2 for reduced ones), written for the
// page: "d/tau" as d/τ, "k_n d^2" as k_n d², "kg/m^3" as kg/m³.
export function unitText(unit) {
  if (!unit) return '';
  return unit.replaceAll('tau', 'τ').replaceAll('^2', '²').replaceAll('^3', '³');
}

// "label (unit)", or the label alone when the unit is unknown (a study whose axes mix unit systems).
export function withUnit(label, unit) {
  return unit ? `${label} (${unitText(unit)})` : label;
}

// "value unit", the number formatted by `format`.
export function valueWithUnit(value, unit, format) {
  const text = format(value);
  return unit && text !== '–' ? `${text} ${unitText(unit)}` : text;
}

// A result's numbers are in reduced units whatever the case's (schemas/result.schema.json); a
// physical case's result gives the SI value of each reduced unit (result.units.physical).
const kReducedUnits = { length: 'd', mass: 'm', time: 'tau', speed: 'd/tau', energy: 'k_n d^2' };

// A case's quantities in its units (GET /api/cases/ID: units): `label(text, kind)` names one kind
// of quantity with its unit, `value(reduced, kind)` converts a result's reduced value to it, and
// `reduced(text, kind)` labels a value kept in reduced units. A physical case without a result
// (nothing to scale by) keeps reduced values, labelled so.
export function caseUnits(detail) {
  const physical = ((detail.result || {}).units || {}).physical;
  const scales = physical ? { length: physical.diameter_m, mass: physical.mass_kg, time: physical.time_s,
    speed: physical.speed_m_per_s, energy: physical.energy_J } : null;
  const names = scales ? detail.units || {} : kReducedUnits;
  return {
    physical: Boolean(scales),
    label: (text, kind) => withUnit(text, names[kind]),
    reduced: (text, kind) => withUnit(text, kReducedUnits[kind]),
    value: (reduced, kind) => (scales && typeof reduced === 'number' ? reduced * scales[kind] : reduced),
  };
}
