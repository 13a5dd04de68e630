#include "engine/impact/impact_result.hpp"

#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <string>

#include "engine/core/units.hpp"
#include "engine/core/version.hpp"

namespace aerobreak {
namespace {

using Json = nlohmann::ordered_json;

template <typename... Args>
std::string formatted(const char* format, Args... args) {
  char text[256];
  std::snprintf(text, sizeof text, format, args...);
  return text;
}

// JSON has no NaN or infinity: a quantity that is undefined is null.
Json number(double x) { return std::isfinite(x) ? Json(x) : Json(nullptr); }
Json vector(const Vec3& v) { return Json::array({number(v.x), number(v.y), number(v.z)}); }

// The energy dissipated by each channel and in total, each written as `value` makes it (the joules
// themselves, or their share of the impact energy).
template <typename Value>
Json dissipation_json(const DissipationTally& d, Value value) {
  return {{"damping", value(d.damping)},   {"friction", value(d.friction)}, {"rolling", value(d.rolling)},
          {"twisting", value(d.twisting)}, {"breaking", value(d.breaking)}, {"total", value(d.dissipated())}};
}

Json budget(const EnergyBudget& e) {
  const DissipationTally& d = e.dissipation;
  return {{"translational_kinetic", number(e.translational_kinetic)},
          {"rotational_kinetic", number(e.rotational_kinetic)},
          {"kinetic", number(e.kinetic())},
          {"contact_elastic", number(e.contact_elastic)},
          {"van_der_waals", number(e.van_der_waals)},
          {"gravitational", number(e.gravitational)},
          {"mechanical", number(e.mechanical())},
          {"dissipated", dissipation_json(d, number)},
          {"stiffness_work", number(d.stiffness_work)},
          {"van_der_waals_handover", number(d.van_der_waals_handover)},
          {"external_work", number(e.external_work)},
          {"balance", number(e.balance())}};
}

Json shape(const ClusterShape& s) {
  return {{"primaries", s.primaries},
          {"radius_of_gyration", number(s.radius_of_gyration)},
          {"fractal_dimension", number(s.fractal_dimension)},
          {"coordination", number(s.coordination)},
          {"filling_factor", number(s.filling_factor)}};
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
          {"landing", f.landing},
          {"bouncing", f.bouncing},
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

double lambda(const ImpactCase& c) {
  return c.material.surface_energy > 0.0 ? adhesion_energy_ratio(c.material, 1.0, c.speed) : 0.0;
}

Json units_json(const ImpactCase& c) {
  Json units = {{"system", c.physical ? "physical" : "reduced"},
                {"length", "d (primary diameter)"},
                {"mass", "m (primary mass)"},
                {"time", "tau = sqrt(m/k_n), k_n of report eq 7 (gravity off)"},
                {"energy", "k_n d^2"},
                {"physical", nullptr}};
  if (c.physical) {
    const PhysicalScaling& s = *c.physical;
    units["physical"] = {{"diameter_m", s.diameter},           {"mass_kg", s.mass()},
                         {"stiffness_N_per_m", s.stiffness()}, {"time_s", s.time_unit()},
                         {"speed_m_per_s", s.speed_unit()},    {"energy_J", s.energy_unit()},
                         {"softening", s.softening},           {"softened_time_s", s.softened_time(1.0)}};
  }
  return units;
}

Json dimensionless_json(const ImpactResult& r) {
  const ImpactCase& c = r.impact_case;
  const bool rolling = c.model.rolling;
  return {{"gamma_over_kn", number(c.material.surface_energy)},
          {"lambda", number(lambda(c))},
          {"kappa", c.model.van_der_waals && c.material.surface_energy > 0.0
                        ? number(kappa(c.material.surface_energy, c.model.hamaker.min_separation))
                        : Json(nullptr)},
          {"primaries", r.primaries},
          {"initial_contacts", r.initial_contacts},
          {"energy_per_contact", number(r.energy_groups.energy_per_contact)},
          {"energy_over_rolling", number(r.energy_groups.energy_over_rolling)},
          {"coordination_before", number(r.before.coordination)},
          {"coordination_after", number(r.after.coordination)},
          {"filling_factor_before", number(r.before.filling_factor)},
          {"filling_factor_after", number(r.after.filling_factor)},
          {"friction", number(c.model.friction)},
          {"critical_rolling_over_d", rolling ? number(c.model.critical_rolling) : Json(nullptr)},
          {"impact_angle_deg", number(c.angle_degrees)},
          {"impact_speed", number(c.speed)},
          {"poisson_ratio", number(c.material.poisson_ratio)},
          {"wall_adhesive", c.wall_adhesive},
          {"wall_gamma_over_kn", number(c.wall_material.surface_energy)},
          {"wall_youngs_modulus_ratio", number(c.wall_material.youngs_modulus / c.material.youngs_modulus)}};
}

Json contact_energies_json(const ContactEnergies& e) {
  const double scale = e.pull_off_force * e.critical_overlap;
  return {{"pull_off_force", number(e.pull_off_force)},
          {"critical_overlap", number(e.critical_overlap)},
          {"equilibrium_overlap", number(e.equilibrium_overlap)},
          {"break_overlap", number(e.break_overlap)},
          {"breaking_energy", number(e.breaking_energy)},
          {"breaking_energy_over_fc_delta_c", scale > 0.0 ? number(e.breaking_energy / scale) : Json(nullptr)},
          {"rolling_energy", number(e.rolling_energy)}};
}

Json setup_json(const ImpactResult& r) {
  const ImpactCase& c = r.impact_case;
  const auto& rot = r.orientation;
  return {{"cluster_source", c.cluster.kind == ClusterSource::Kind::generated ? c.cluster.generator.method : "file"},
          {"relaxation",
           {{"performed", r.relaxation.performed},
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
          {"impact_kinetic_energy", number(r.impact_kinetic_energy)},
          {"contact_energies", contact_energies_json(r.contact_energies)}};
}

const char* time_step_source(const ImpactResult& r) {
  if (r.impact_case.time_step > 0.0) return "fixed";
  return r.adaptive_time_step ? "adaptive" : "automatic";
}

// The steps the run took (docs/MODEL.md 9.2) and how well its contact events were resolved.
Json step_history_json(const ImpactResult& r) {
  const StepHistory& h = r.step_history;
  return {{"shortest", number(h.shortest)},
          {"longest", number(h.longest)},
          {"mean", number(h.mean())},
          {"steps_at_contact_period", h.contact_period_steps},
          {"steps_at_break_overlap", h.break_overlap_steps},
          {"choices", h.choices},
          {"fewest_steps_per_break_overlap",
           {{"pairs", number(r.pair_events.fewest_steps_per_break_overlap)},
            {"wall", number(r.wall_events.fewest_steps_per_break_overlap)}}}};
}

Json run_json(const ImpactResult& r) {
  const ImpactCase& c = r.impact_case;
  const TimeStepEstimate& est = r.time_step_estimate;
  return {{"time_step", number(r.time_step)},
          {"time_step_source", time_step_source(r)},
          {"time_step_history", step_history_json(r)},
          {"time_step_estimate",
           {{"limit", est.period > 0.0 ? Json(time_step_limit_name(est.limit)) : Json(nullptr)},
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
          {"settled_by", r.settled ? Json(to_string(r.settled_by)) : Json(nullptr)},
          {"settled_at", r.settled ? number(r.settled_at) : Json(nullptr)},
          {"quiet_since", r.settled ? number(r.quiet_since) : Json(nullptr)},
          {"quiet_window", number(r.quiet_window)},
          {"rest_speed", number(r.rest_speed)},
          {"unsettled_reason", r.settled ? Json(nullptr) : Json(r.unsettled_reason)},
          {"wall_clock_seconds", number(r.wall_clock_seconds)},
          {"cpu_seconds", number(r.cpu_seconds)},
          {"particle_steps_per_second", number(r.particle_steps_per_second)},
          {"particle_steps_per_cpu_second", number(r.particle_steps_per_cpu_second)},
          {"neighbor_builds", r.neighbor_builds},
          {"snapshots", r.snapshots}};
}

// The fragments that left the wall: primaries, mass, normal velocity and speed (the window-mean
// velocity when settled), heaviest first as listed in /fragments/list.
Json reentrained_json(const ImpactResult& r) {
  Json list = Json::array();
  for (const std::size_t k : r.classification.reentrained) {
    const Vec3& v = r.fragment_final_velocity[k];
    list.push_back({{"primaries", r.fragments[k].size},
                    {"mass", number(r.fragments[k].mass)},
                    {"normal_velocity", number(dot(v, r.wall_normal))},
                    {"speed", number(norm(v))}});
  }
  return list;
}

Json outcome_json(const ImpactResult& r) {
  const ImpactCase& c = r.impact_case;
  const Classification& k = r.classification;
  return {
      {"class", to_string(k.outcome)},
      {"reason", k.reason},
      {"fractured_on_wall", k.fractured_on_wall},
      {"retained_mass_fraction", number(k.retained_mass_fraction)},
      {"reentrained_mass_fraction", number(k.reentrained_mass_fraction)},
      {"reentrained_fragments", reentrained_json(r)},
      {"damage_ratio", number(r.damage_ratio())},
      {"thresholds",
       {{"largest_fragment_share", number(c.thresholds.bounce_share)},
        {"rest_speed_fraction", number(c.settle.rest_speed_fraction)},
        {"quiet_window", number(r.quiet_window)}}},
      {"largest_fragment_share", number(k.largest_fragment_share)},
      {"largest_reentrained_share", number(k.largest_reentrained_share)},
      {"fragment_count", r.fragments.size()},
      {"restitution", {{"normal", number(r.restitution_normal)}, {"tangential", number(r.restitution_tangential)}}}};
}

Json strain_json(const StrainMeasure& m) {
  return {{"overlap_ratio", number(m.overlap_ratio)}, {"contact_radius_ratio", number(m.contact_radius_ratio)}};
}

Json validity_json(const SmallStrainCheck& v) {
  return {{"small_strain", v.within},
          {"deepest_overlap_ratio", number(v.worst.overlap_ratio)},
          {"largest_contact_radius_ratio", number(v.worst.contact_radius_ratio)},
          {"pair", strain_json(v.pair)},
          {"wall", strain_json(v.wall)},
          {"limits", strain_json({v.limits.overlap_ratio, v.limits.contact_radius_ratio})},
          {"bound", v.bound}};
}

Json contacts_json(const ImpactResult& r) {
  return {{"initial", r.initial_contacts},
          {"final", r.final_contacts},
          {"final_wall", r.final_wall_contacts},
          {"made", r.pair_events.made},
          {"broken", r.pair_events.broken},
          {"initial_broken", r.initial_contacts_broken},
          {"wall_made", r.wall_events.made},
          {"wall_broken", r.wall_events.broken},
          {"deepest_overlap_ratio", number(r.pair_events.deepest_overlap_ratio)},
          {"deepest_wall_overlap_ratio", number(r.wall_events.deepest_overlap_ratio)}};
}

Json energy_json(const ImpactResult& r) {
  const EnergyBudget& e0 = r.initial_energy;
  const EnergyBudget& e1 = r.final_energy;
  const double e_impact = r.impact_kinetic_energy;
  const DissipationTally& d = e1.dissipation;
  const auto share = [&](double x) { return number(e_impact > 0.0 ? x / e_impact : NAN); };
  return {{"initial", budget(e0)},
          {"final", budget(e1)},
          {"impact_kinetic", number(e_impact)},
          {"final_fragment_translational_kinetic", number(r.fragment_translational_kinetic)},
          {"final_internal_kinetic", number(e1.kinetic() - r.fragment_translational_kinetic)},
          {"dissipated_share", dissipation_json(d, share)},
          {"balance_change", number(e1.balance() - e0.balance())},
          {"balance_drift", number((e1.balance() - e0.balance()) / (e_impact + d.dissipated()))}};
}

Json fragments_json(const ImpactResult& r) {
  Json distribution = Json::array();
  for (const auto& [size, count] : size_distribution(r.fragments))
    distribution.push_back({{"size", size}, {"count", count}});
  Json list = Json::array();
  for (std::size_t k = 0; k < r.fragments.size(); ++k)
    list.push_back(fragment(
        r.fragments[k], k < r.fragment_mean_velocity.size() ? &r.fragment_mean_velocity[k] : nullptr, r.wall_normal));
  return {{"size_distribution", distribution}, {"list", list}};
}

// The dimensional outputs of a physical case in SI (docs/IMPACT.md section 5); null otherwise.
Json si_json(const ImpactResult& r) {
  const ImpactCase& c = r.impact_case;
  if (!c.physical) return nullptr;
  const PhysicalScaling& u = *c.physical;
  const auto seconds = [&](double t) { return number(u.physical_time(t)); };
  const auto metres_per_second = [&](double v) { return number(u.physical_speed(v)); };
  const auto joules = [&](double e) { return number(e * u.energy_unit()); };
  const Vec3& n = r.wall_normal;
  const Vec3 tangent = r.impact_velocity - dot(r.impact_velocity, n) * n;
  Json reentrained = Json::array();
  for (const std::size_t k : r.classification.reentrained) {
    const Vec3& v = r.fragment_final_velocity[k];
    reentrained.push_back({{"primaries", r.fragments[k].size},
                           {"mass_kg", number(r.fragments[k].mass * u.mass())},
                           {"normal_velocity_m_per_s", metres_per_second(dot(v, n))},
                           {"speed_m_per_s", metres_per_second(norm(v))}});
  }
  return {{"time_step_s", seconds(r.time_step)},
          {"time_limit_s", seconds(c.time_limit)},
          {"simulated_time_s", seconds(r.simulated_time)},
          {"settled_at_s", r.settled ? seconds(r.settled_at) : Json(nullptr)},
          {"quiet_window_s", seconds(r.quiet_window)},
          {"impact_speed_m_per_s", metres_per_second(c.speed)},
          {"rest_speed_m_per_s", metres_per_second(r.rest_speed)},
          {"restitution_inputs",
           {{"impact_normal_velocity_m_per_s", metres_per_second(dot(r.impact_velocity, n))},
            {"impact_tangential_speed_m_per_s", metres_per_second(norm(tangent))},
            {"rebound_velocity_m_per_s",
             Json::array({metres_per_second(r.rebound_velocity.x), metres_per_second(r.rebound_velocity.y),
                          metres_per_second(r.rebound_velocity.z)})},
            {"rebound_normal_velocity_m_per_s", metres_per_second(dot(r.rebound_velocity, n))}}},
          {"impact_kinetic_energy_J", joules(r.impact_kinetic_energy)},
          {"breaking_energy_J", joules(r.contact_energies.breaking_energy)},
          {"rolling_energy_J", joules(r.contact_energies.rolling_energy)},
          {"final_kinetic_energy_J", joules(r.final_energy.kinetic())},
          {"dissipated_energy_J", joules(r.final_energy.dissipation.dissipated())},
          {"reentrained_fragments", reentrained}};
}

}  // namespace

nlohmann::ordered_json to_json(const ImpactResult& r) {
  Json compaction = {{"before", shape(r.before)},
                     {"after", shape(r.after)},
                     {"radius_of_gyration_ratio", number(r.after.radius_of_gyration / r.before.radius_of_gyration)}};
  return {
      {"format", "aerobreak-impact-result"},
      {"format_version", 2},
      {"code", {{"name", "aerobreak"}, {"version", std::string(version())}, {"git_commit", std::string(git_commit())}}},
      {"case", r.impact_case.document},
      {"units", units_json(r.impact_case)},
      {"dimensionless", dimensionless_json(r)},
      {"setup", setup_json(r)},
      {"run", run_json(r)},
      {"outcome", outcome_json(r)},
      {"validity", validity_json(r.validity)},
      {"contacts", contacts_json(r)},
      {"compaction", compaction},
      {"energy", energy_json(r)},
      {"fragments", fragments_json(r)},
      {"si", si_json(r)}};
}

double ImpactResult::damage_ratio() const {
  return initial_contacts > 0 ? static_cast<double>(initial_contacts_broken) / static_cast<double>(initial_contacts)
                              : std::numeric_limits<double>::quiet_NaN();
}

namespace {

// E_roll (eq 18's rolling energy) and E_kin / E_roll, or that the case has no rolling resistance.
std::string rolling_line(const ImpactResult& r, const std::string& si_value) {
  const double rolling_energy = r.contact_energies.rolling_energy;
  if (!r.impact_case.model.rolling)
    return "E_roll: no rolling resistance (/model/rolling/enabled is false), so no E_kin / E_roll\n";
  return formatted("E_roll = %.6g k_n d^2", rolling_energy) + si_value +
         formatted(", E_kin / E_roll = %.6g\n", r.energy_groups.energy_over_rolling);
}

}  // namespace

std::string describe_setup(const ImpactResult& r) {
  const ImpactCase& c = r.impact_case;
  const ContactEnergies& e = r.contact_energies;
  // " = <value in SI> <unit>" for a physical case, nothing for a reduced one.
  const auto si = [&](double reduced, double unit, const char* name) {
    return c.physical ? " = " + formatted("%.4g", reduced * unit) + " " + name : std::string();
  };
  const double time_unit = c.physical ? c.physical->time_unit() : 0.0;
  const double energy_unit = c.physical ? c.physical->energy_unit() : 0.0;
  const double scale = e.pull_off_force * e.critical_overlap;
  return "time unit tau = sqrt(m/k_n)" + si(1.0, time_unit, "s") + "\n" + formatted("time step %.6g tau", r.time_step) +
         si(r.time_step, time_unit, "s") +
         (r.adaptive_time_step
              ? formatted(" (adaptive: chosen again from the speeds of the moment, at most %.6g tau, %.4g steps per "
                          "contact period)\n",
                          r.time_step_estimate.period / r.time_step_estimate.steps_per_period,
                          r.time_step_estimate.steps_per_period)
              : formatted(" (%s, %.4g steps per contact period)\n", time_step_source(r),
                          r.time_step_estimate.steps_per_period)) +
         formatted("lambda (eq 19) = %.6g\n", lambda(c)) +
         formatted("N = %zu primaries, N_c = %zu initial contacts, coordination %.4g, filling factor %.4g\n",
                   r.primaries, r.initial_contacts, r.before.coordination, r.before.filling_factor) +
         formatted("E_kin = %.6g k_n d^2", r.impact_kinetic_energy) + si(r.impact_kinetic_energy, energy_unit, "J") +
         "\n" + formatted("E_break = %.6g k_n d^2", e.breaking_energy) + si(e.breaking_energy, energy_unit, "J") +
         formatted(" (%.4f F_c delta_c), E_kin / (N_c E_break) = %.6g\n", scale > 0.0 ? e.breaking_energy / scale : NAN,
                   r.energy_groups.energy_per_contact) +
         rolling_line(r, si(e.rolling_energy, energy_unit, "J"));
}

std::vector<SchemaViolation> validate_result(const nlohmann::ordered_json& document) {
  return result_schema().validate(document);
}

}  // namespace aerobreak
