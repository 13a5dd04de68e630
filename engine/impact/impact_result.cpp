#include "engine/impact/impact_result.hpp"

#include <cmath>
#include <numbers>

#include "engine/core/units.hpp"
#include "engine/core/version.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

// JSON has no NaN or infinity: a quantity that is undefined is null.
Json number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }
Json vector(const Vec3& v) { return Json::array({number(v.x), number(v.y), number(v.z)}); }

Json budget(const EnergyBudget& e) {
  const DissipationTally& d = e.dissipation;
  return {{"translational_kinetic", number(e.translational_kinetic)},
          {"rotational_kinetic", number(e.rotational_kinetic)},
          {"kinetic", number(e.kinetic())},
          {"contact_elastic", number(e.contact_elastic)},
          {"van_der_waals", number(e.van_der_waals)},
          {"gravitational", number(e.gravitational)},
          {"mechanical", number(e.mechanical())},
          {"dissipated", {{"damping", number(d.damping)},
                          {"friction", number(d.friction)},
                          {"rolling", number(d.rolling)},
                          {"twisting", number(d.twisting)},
                          {"breaking", number(d.breaking)},
                          {"total", number(d.dissipated())}}},
          {"stiffness_work", number(d.stiffness_work)},
          {"van_der_waals_handover", number(d.van_der_waals_handover)},
          {"external_work", number(e.external_work)},
          {"balance", number(e.balance())}};
}

Json shape(const ClusterShape& s) {
  return {{"primaries", s.primaries},
          {"radius_of_gyration", number(s.radius_of_gyration)},
          {"fractal_dimension", number(s.fractal_dimension)},
          {"coordination", number(s.coordination)}};
}

Json fragment(const Fragment& f, const Vec3* mean_velocity, const Vec3& wall_normal) {
  return {{"size", f.size},
          {"mass", number(f.mass)},
          {"centre_of_mass", vector(f.centre_of_mass)},
          {"velocity", vector(f.velocity)},
          {"normal_velocity", number(f.normal_velocity)},
          {"mean_velocity", mean_velocity ? vector(*mean_velocity) : Json(nullptr)},
          {"mean_normal_velocity", mean_velocity ? number(dot(*mean_velocity, wall_normal)) : Json(nullptr)},
          {"on_wall", f.on_wall()},
          {"wall_contacts", f.wall_contacts},
          {"lowest_gap", number(f.lowest_gap)},
          {"radius_of_gyration", number(f.radius_of_gyration)},
          {"bounding_radius", number(f.bounding_radius)},
          {"first_primary", f.first_primary}};
}

// kappa of eq 6 with eq 7 substituted (docs/MODEL.md 1.3: the report's second form lacks 2^(-1/3)).
double kappa(double gamma_over_kn, double z0) {
  return 32.0 / (3.0 * std::numbers::pi) * std::cbrt(0.5) / z0 * std::cbrt(gamma_over_kn * gamma_over_kn);
}

}  // namespace

nlohmann::ordered_json to_json(const ImpactResult& r) {
  const ImpactCase& c = r.impact_case;
  const EnergyBudget& e0 = r.initial_energy;
  const EnergyBudget& e1 = r.final_energy;
  const double e_impact = r.impact_kinetic_energy;

  Json units = {{"system", c.physical ? "physical" : "reduced"},
                {"length", "d (primary diameter)"},
                {"mass", "m (primary mass)"},
                {"time", "tau = sqrt(m/k_n), k_n of report eq 7 (gravity off)"},
                {"energy", "k_n d^2"},
                {"physical", nullptr}};
  if (c.physical) {
    const PhysicalScaling& s = *c.physical;
    units["physical"] = {{"diameter_m", s.diameter},
                         {"mass_kg", s.mass()},
                         {"stiffness_N_per_m", s.stiffness()},
                         {"time_s", s.time_unit()},
                         {"speed_m_per_s", s.speed_unit()},
                         {"energy_J", s.energy_unit()},
                         {"softening", s.softening},
                         {"softened_time_s", s.softened_time(1.0)}};
  }

  const bool rolling = c.model.rolling;
  Json dimensionless = {
      {"gamma_over_kn", number(c.material.surface_energy)},
      {"lambda", number(c.material.surface_energy > 0.0 ? adhesion_energy_ratio(c.material, 1.0, c.speed) : 0.0)},
      {"kappa", c.model.van_der_waals && c.material.surface_energy > 0.0
                    ? number(kappa(c.material.surface_energy, c.model.hamaker.min_separation))
                    : Json(nullptr)},
      {"primaries", r.primaries},
      {"friction", number(c.model.friction)},
      {"critical_rolling_over_d", rolling ? number(c.model.critical_rolling) : Json(nullptr)},
      {"impact_angle_deg", number(c.angle_degrees)},
      {"impact_speed", number(c.speed)},
      {"poisson_ratio", number(c.material.poisson_ratio)},
      {"wall_adhesive", c.wall_adhesive},
      {"wall_gamma_over_kn", number(c.wall_material.surface_energy)},
      {"wall_youngs_modulus_ratio", number(c.wall_material.youngs_modulus / c.material.youngs_modulus)}};

  const auto& rot = r.orientation;
  Json setup = {
      {"cluster_source", c.cluster.kind == ClusterSource::Kind::generated ? c.cluster.generator.method : "file"},
      {"relaxation", {{"performed", r.relaxation.performed},
                      {"converged", r.relaxation.converged},
                      {"steps", r.relaxation.steps},
                      {"contacts", r.relaxation.contacts},
                      {"contacts_broken", r.relaxation.contacts_broken},
                      {"wall_clock_seconds", number(r.relaxation.wall_clock_seconds)}}},
      {"orientation", Json::array({vector(rot.row0), vector(rot.row1), vector(rot.row2)})},
      {"wall_normal", vector(r.wall_normal)},
      {"gap", number(c.gap)},
      {"impact_velocity", vector(r.impact_velocity)},
      {"impact_speed", number(c.speed)},
      {"impact_speed_m_per_s", c.physical ? number(c.physical->physical_speed(c.speed)) : Json(nullptr)},
      {"impact_kinetic_energy", number(e_impact)}};

  const TimeStepEstimate& est = r.time_step_estimate;
  Json run = {
      {"time_step", number(r.time_step)},
      {"time_step_source", c.time_step > 0.0 ? "fixed" : "automatic"},
      {"time_step_estimate", {{"limit", c.time_step > 0.0 ? Json(nullptr) : Json(time_step_limit_name(est.limit))},
                              {"period", number(est.period)},
                              {"stiffness", number(est.stiffness)},
                              {"mass", number(est.mass)},
                              {"overlap", number(est.overlap)},
                              {"steps_per_period", number(est.steps_per_period)},
                              {"crossing_time", number(est.crossing_time)},
                              {"break_overlap", number(est.break_overlap)},
                              {"approach_speed", number(est.approach_speed)},
                              {"steps_per_break_overlap", number(est.steps_per_break_overlap)}}},
      {"steps", r.steps},
      {"simulated_time", number(r.simulated_time)},
      {"simulated_time_s", c.physical ? number(c.physical->physical_time(r.simulated_time)) : Json(nullptr)},
      {"time_limit", number(c.time_limit)},
      {"settled", r.settled},
      {"settled_at", r.settled ? number(r.settled_at) : Json(nullptr)},
      {"quiet_since", r.settled ? number(r.quiet_since) : Json(nullptr)},
      {"quiet_window", number(r.quiet_window)},
      {"rest_speed", number(r.rest_speed)},
      {"unsettled_reason", r.settled ? Json(nullptr) : Json(r.unsettled_reason)},
      {"wall_clock_seconds", number(r.wall_clock_seconds)},
      {"particle_steps_per_second", number(r.particle_steps_per_second)},
      {"neighbor_builds", r.neighbor_builds},
      {"snapshots", r.snapshots}};

  Json outcome = {
      {"class", to_string(r.classification.outcome)},
      {"reason", r.classification.reason},
      {"thresholds", {{"largest_fragment_share", number(c.largest_fragment_share)},
                      {"rest_speed_fraction", number(c.settle.rest_speed_fraction)},
                      {"quiet_window", number(r.quiet_window)}}},
      {"largest_fragment_share", number(r.classification.largest_fragment_share)},
      {"fragment_count", r.fragments.size()},
      {"restitution", {{"normal", number(r.restitution_normal)}, {"tangential", number(r.restitution_tangential)}}},
      {"mass_fraction_on_wall", number(r.mass_fraction_on_wall)}};

  Json contacts = {{"initial", r.initial_contacts},
                   {"final", r.final_contacts},
                   {"final_wall", r.final_wall_contacts},
                   {"made", r.pair_events.made},
                   {"broken", r.pair_events.broken},
                   {"wall_made", r.wall_events.made},
                   {"wall_broken", r.wall_events.broken},
                   {"deepest_overlap_ratio", number(r.pair_events.deepest_overlap_ratio)},
                   {"deepest_wall_overlap_ratio", number(r.wall_events.deepest_overlap_ratio)}};

  Json compaction = {{"before", shape(r.before)},
                     {"after", shape(r.after)},
                     {"radius_of_gyration_ratio", number(r.after.radius_of_gyration / r.before.radius_of_gyration)}};

  const DissipationTally& d = e1.dissipation;
  const auto share = [&](double x) { return number(e_impact > 0.0 ? x / e_impact : NAN); };
  Json energy = {{"initial", budget(e0)},
                 {"final", budget(e1)},
                 {"impact_kinetic", number(e_impact)},
                 {"final_fragment_translational_kinetic", number(r.fragment_translational_kinetic)},
                 {"final_internal_kinetic", number(e1.kinetic() - r.fragment_translational_kinetic)},
                 {"dissipated_share", {{"damping", share(d.damping)},
                                       {"friction", share(d.friction)},
                                       {"rolling", share(d.rolling)},
                                       {"twisting", share(d.twisting)},
                                       {"breaking", share(d.breaking)},
                                       {"total", share(d.dissipated())}}},
                 {"balance_change", number(e1.balance() - e0.balance())},
                 {"balance_drift", number((e1.balance() - e0.balance()) / (e_impact + d.dissipated()))}};

  Json distribution = Json::array();
  for (const auto& [size, count] : size_distribution(r.fragments)) distribution.push_back({{"size", size}, {"count", count}});
  Json list = Json::array();
  for (std::size_t k = 0; k < r.fragments.size(); ++k)
    list.push_back(fragment(r.fragments[k], k < r.fragment_mean_velocity.size() ? &r.fragment_mean_velocity[k] : nullptr,
                            r.wall_normal));

  return {{"format", "aerobreak-impact-result"},
          {"format_version", 1},
          {"code", {{"name", "aerobreak"}, {"version", std::string(version())}, {"git_commit", std::string(git_commit())}}},
          {"case", c.document},
          {"units", units},
          {"dimensionless", dimensionless},
          {"setup", setup},
          {"run", run},
          {"outcome", outcome},
          {"contacts", contacts},
          {"compaction", compaction},
          {"energy", energy},
          {"fragments", {{"size_distribution", distribution}, {"list", list}}}};
}

std::vector<SchemaViolation> validate_result(const nlohmann::ordered_json& document) {
  return result_schema().validate(document);
}

}  // namespace aerobreak
