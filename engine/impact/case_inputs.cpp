#include "engine/impact/case_inputs.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

constexpr double kNotGiven = std::numeric_limits<double>::quiet_NaN();

const Json* member(const Json& object, const char* name) {
  if (!object.is_object()) return nullptr;
  const auto found = object.find(name);
  return found == object.end() ? nullptr : &*found;
}

double number_of(const Json& object, const char* name, double fallback = kNotGiven) {
  const Json* value = member(object, name);
  return value && value->is_number() ? value->get<double>() : fallback;
}

const Json& object_of(const Json& object, const char* name) {
  static const Json empty = Json::object();
  const Json* value = member(object, name);
  return value ? *value : empty;
}

PhysicalScaling physical_scaling(const Json& material) {
  PhysicalScaling scaling;
  scaling.material.youngs_modulus = number_of(material, "youngs_modulus");
  scaling.material.poisson_ratio = number_of(material, "poisson_ratio");
  scaling.material.density = number_of(material, "density");
  scaling.material.surface_energy = number_of(material, "surface_energy");
  scaling.diameter = number_of(material, "diameter");
  scaling.softening = number_of(material, "softening", 1.0);
  return scaling;
}

void read_generator(const Json& generator, CaseInputs& inputs) {
  // An integer, as the schema asks; a study's range may have written it as a whole double.
  const double n = number_of(generator, "primaries");
  if (n >= 1.0 && n == std::floor(n)) inputs.primaries = static_cast<std::int64_t>(n);
  if (const Json* df = member(generator, "fractal_dimension"); df && df->is_number())
    inputs.fractal_dimension = df->get<double>();
}

}  // namespace

CaseInputs read_case_inputs(const Json& document) {
  CaseInputs inputs;
  const Json& material = object_of(document, "material");
  const Json& impact = object_of(document, "impact");
  const Json* units = member(document, "units");
  const double speed = number_of(impact, "speed");
  if (units && units->is_string() && units->get<std::string>() == "physical") {
    inputs.physical = physical_scaling(material);
    inputs.material = inputs.physical->reduced();
    inputs.speed = inputs.physical->reduced_speed(speed);
  } else {
    inputs.material = reduced_material(number_of(material, "gamma_over_kn"), number_of(material, "poisson_ratio"));
    inputs.speed = speed;
  }
  inputs.angle_degrees = number_of(impact, "angle", 0.0);
  read_generator(object_of(object_of(document, "cluster"), "generator"), inputs);
  return inputs;
}

}  // namespace aerobreak
