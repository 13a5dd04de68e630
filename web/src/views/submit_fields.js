// The fields of the submit form for the common physical study (docs/WEB.md): each names the study
// field it writes (a JSON pointer; for an axis, `base` names the one value a study without the
// axis sets in its base instead), how its text reads (a field of the case takes its label and
// unit from the service, caseFieldNames; a field of the study alone has its own `label`), the
// limits of the schema at that field (`schema` names where: the browser test compares them with
// the schema files) and, where a value is allowed but unlikely for an aerosol cluster, the range
// outside which the form says so without refusing it. Pure data and functions: no DOM, so that
// node reads them too.

// A number as JSON writes it: no units, no thousands separators.
const kNumber = /^[+-]?(\d+\.?\d*|\.\d+)([eE][+-]?\d+)?$/;

const kMaterial = 'case.schema.json#/$defs/physical_material/properties';
const kGenerator = 'case.schema.json#/$defs/generator/properties';
const kReplicates = 'study.schema.json#/properties/replicates/properties';

export const kFormFields = [
  { id: 'name', label: 'Name', pointer: '/name', kind: 'text', minLength: 1, maxLength: 200,
    schema: 'study.schema.json#/properties/name' },
  { id: 'description', label: 'Description', pointer: '/description', kind: 'text',
    schema: 'study.schema.json#/properties/description' },
  { id: 'youngs_modulus', pointer: '/base/material/youngs_modulus',
    kind: 'number', minimum: 1e5, maximum: 2e12, usual: [1e6, 1e12], schema: `${kMaterial}/youngs_modulus`,
    material: true },
  { id: 'poisson_ratio', pointer: '/base/material/poisson_ratio', kind: 'number',
    exclusiveMinimum: -1, exclusiveMaximum: 0.5, schema: `${kMaterial}/poisson_ratio`, material: true },
  { id: 'density', pointer: '/base/material/density', kind: 'number',
    minimum: 100, maximum: 30000, usual: [100, 25000], schema: `${kMaterial}/density`, material: true },
  { id: 'surface_energy', pointer: '/base/material/surface_energy',
    kind: 'number', minimum: 0, maximum: 10, usual: [0, 5], schema: `${kMaterial}/surface_energy`, material: true },
  { id: 'diameter', pointer: '/base/material/diameter', kind: 'number',
    minimum: 1e-9, maximum: 1e-3, usual: [1e-9, 1e-5], schema: `${kMaterial}/diameter`, material: true },
  { id: 'speeds', pointer: '/axes/impact_speed/values', kind: 'numbers',
    exclusiveMinimum: 0, usual: [0, 1000], schema: 'case.schema.json#/$defs/impact/properties/speed',
    base: '/base/impact/speed' },
  { id: 'primaries', pointer: '/axes/primaries/values', kind: 'integers',
    minimum: 1, maximum: 10000000, usual: [2, 100000], schema: `${kGenerator}/primaries`,
    base: '/base/cluster/generator/primaries' },
  { id: 'generator', pointer: '/base/cluster/generator/method', kind: 'choice',
    options: [['ballistic', 'ballistic cluster-cluster'], ['dlca', 'diffusion-limited (DLCA)'],
      ['tunable', 'tunable D_f, k_f']],
    schema: `${kGenerator}/method` },
  { id: 'fractal_dimension', pointer: '/base/cluster/generator/fractal_dimension',
    kind: 'number', minimum: 1.5, maximum: 2.8, only: 'tunable', initial: 1.8,
    schema: `${kGenerator}/fractal_dimension` },
  { id: 'prefactor', pointer: '/base/cluster/generator/prefactor', kind: 'number',
    exclusiveMinimum: 0, only: 'tunable', initial: 1.3, schema: `${kGenerator}/prefactor` },
  { id: 'replicates', label: 'replicates', pointer: '/replicates/count', kind: 'integer', minimum: 1, maximum: 1000,
    schema: `${kReplicates}/count` },
  { id: 'seed', label: 'study seed', pointer: '/replicates/seed', kind: 'integer', minimum: 0,
    maximum: 9007199254740991, schema: `${kReplicates}/seed` },
];

// The wall axis: adhesive (JKR with the primaries' material), without adhesion (Hertz), or both.
export const kWallPointer = '/axes/~1wall~1adhesive/values';
// Fields a generator takes beyond the common ones (engine/impact/cluster_generators.cpp): switching
// the generator removes the others' fields, which the study would refuse.
export const kGeneratorFields = { ballistic: [], dlca: ['sintering'], tunable: ['fractal_dimension', 'prefactor'] };

// The case field a form field sets (/material/density), or null for a field of the study alone.
export function casePointer(field) {
  const pointer = field.base || field.pointer;
  return pointer.startsWith('/base/') ? pointer.slice('/base'.length) : null;
}

// A form field's label and its unit in a physical or reduced study, from the service's case fields
// (GET /api/case-fields: items); a case field the service does not describe is named by its
// pointer, without a unit.
export function caseFieldNames(field, caseFields, physical) {
  const pointer = casePointer(field);
  if (!pointer) return { label: field.label, unit: null };
  const described = caseFields.find((item) => item.pointer === pointer);
  if (!described) return { label: pointer, unit: null };
  return { label: described.label, unit: described.units[physical ? 'physical' : 'reduced'] };
}

// What one value breaks of the field's limits, or null.
function limitProblem(value, field) {
  const { minimum, exclusiveMinimum, maximum, exclusiveMaximum } = field;
  if (exclusiveMinimum !== undefined && !(value > exclusiveMinimum)) return `must be greater than ${exclusiveMinimum}`;
  if (minimum !== undefined && !(value >= minimum)) return `must be at least ${minimum}`;
  if (exclusiveMaximum !== undefined && !(value < exclusiveMaximum)) return `must be less than ${exclusiveMaximum}`;
  if (maximum !== undefined && !(value <= maximum)) return `must be at most ${maximum}`;
  return null;
}

function readNumber(text, integer) {
  if (!kNumber.test(text)) return { error: `“${text}” is not a number (write e.g. 2.5e10, without units)` };
  const value = Number(text);
  if (integer && !Number.isInteger(value)) return { error: `“${text}” is not a whole number` };
  return { value };
}

// Reads a field's text: {value} or {error}.
export function readField(field, text) {
  const trimmed = text.trim();
  if (field.kind === 'text') {
    if (trimmed.length < (field.minLength || 0)) return { error: 'must not be empty' };
    if (field.maxLength && text.length > field.maxLength)
      return { error: `must be at most ${field.maxLength} characters` };
    return { value: text };
  }
  if (field.kind === 'choice') return { value: text };
  if (field.kind === 'number' || field.kind === 'integer') {
    if (!trimmed) return { error: 'needs a value' };
    const read = readNumber(trimmed, field.kind === 'integer');
    if (read.error) return read;
    const problem = limitProblem(read.value, field);
    return problem ? { error: problem } : read;
  }
  const items = trimmed.split(/[\s,;]+/).filter(Boolean);
  if (items.length === 0) return { error: 'needs at least one value' };
  const values = [];
  for (const item of items) {
    const read = readNumber(item, field.kind === 'integers');
    if (read.error) return read;
    const problem = limitProblem(read.value, field);
    if (problem) return { error: `${item}: ${problem}` };
    if (values.includes(read.value)) return { error: `${item} is listed twice` };
    values.push(read.value);
  }
  return { value: values };
}

// A note on an allowed but unusual value (outside field.usual), or null.
export function unusualValue(field, value) {
  if (!field.usual) return null;
  const [low, high] = field.usual;
  const outside = (Array.isArray(value) ? value : [value])
    .filter((v) => typeof v === 'number' && (v < low || v > high));
  return outside.length ? `${outside.join(', ')}: unusual here (usually ${low} to ${high}); check the unit` : null;
}

// A number as the user would write it: 2.5e10 rather than 25000000000.
const numberText = (value) => {
  const magnitude = Math.abs(value);
  const exponent = typeof value === 'number' && value !== 0 && (magnitude >= 1e6 || magnitude < 1e-3);
  return exponent ? value.toExponential().replace('e+', 'e') : String(value);
};

// A field's value as its text.
export function fieldText(field, value) {
  if (value === undefined || value === null) return '';
  const text = field.kind === 'number' || field.kind === 'numbers' ? numberText : String;
  return Array.isArray(value) ? value.map(text).join(', ') : text(value);
}
