#pragma once
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "engine/cluster/rotation.hpp"
#include "engine/dem/contact_forces.hpp"
#include "engine/dem/energy_budget.hpp"
#include "engine/dem/step_chooser.hpp"
#include "engine/dem/time_step.hpp"
#include "engine/impact/contact_scales.hpp"
#include "engine/impact/fragments.hpp"
#include "engine/impact/impact_case.hpp"
#include "engine/impact/json_schema.hpp"
#include "engine/impact/outcome.hpp"
#include "engine/impact/settle.hpp"

namespace aerobreak {

// Structure of a cluster (or of the largest fragment) before or after the impact.
struct ClusterShape {
  std::size_t primaries = 0;
  double radius_of_gyration = 0.0;  // of the primaries' centres, mass-weighted (cluster_analysis.hpp)
  double fractal_dimension = 0.0;   // mass-radius dimension (cluster_analysis.hpp); NaN when Rg < 8 d
  double coordination = 0.0;        // 2 x particle-particle contacts / primaries
  double filling_factor = 0.0;      // within sqrt(5/3) Rg (cluster_analysis.hpp); NaN for one primary
};

struct RelaxationSummary {
  bool performed = false;
  bool converged = false;
  std::int64_t steps = 0;
  std::size_t contacts = 0;
  std::uint64_t contacts_broken = 0;
  double wall_clock_seconds = 0.0;
};

// Everything one impact run produces (schemas/result.schema.json is its JSON form). Reduced units.
struct ImpactResult {
  ImpactCase impact_case;

  // Set-up
  std::size_t primaries = 0;
  Rotation orientation;
  Vec3 wall_normal{0.0, 0.0, 1.0};
  Vec3 impact_velocity;
  double impact_kinetic_energy = 0.0;  // of the whole cluster, 1/2 M v^2
  RelaxationSummary relaxation;
  ContactEnergies contact_energies;  // of two primaries of diameter d (the geometric mean)
  EnergyGroups energy_groups;        // E_kin / (N_c E_break), E_kin / E_roll

  // Run
  TimeStepEstimate time_step_estimate;  // the automatic step at the impact speed (also for a fixed step)
  double time_step = 0.0;               // the first step
  bool adaptive_time_step = false;      // chosen again during the run from the speeds of the moment
  StepHistory step_history;
  std::int64_t steps = 0;
  double simulated_time = 0.0;
  bool settled = false;
  SettleRule settled_by = SettleRule::quiet;  // when settled
  double settled_at = 0.0;
  double quiet_since = 0.0;
  double quiet_window = 0.0;
  double rest_speed = 0.0;
  std::string unsettled_reason;                // the settle criterion's last objection (undetermined runs)
  double wall_clock_seconds = 0.0;             // of stepping
  double cpu_seconds = 0.0;                    // of stepping, the run's thread
  double particle_steps_per_second = 0.0;      // by the wall clock
  double particle_steps_per_cpu_second = 0.0;  // by CPU time
  std::uint64_t neighbor_builds = 0;
  std::size_t snapshots = 0;

  // Contacts
  std::size_t initial_contacts = 0;  // particle-particle, at the start of the impact run
  std::size_t final_contacts = 0;
  std::size_t final_wall_contacts = 0;
  ContactEvents pair_events;  // made and broken during the impact (the starting bonds not counted)
  ContactEvents wall_events;
  std::size_t initial_contacts_broken = 0;  // initial contacts no longer present at the end
  double damage_ratio() const;              // initial_contacts_broken / initial_contacts; NaN without any

  // Outcome
  std::vector<Fragment> fragments;            // largest first
  std::vector<Vec3> fragment_mean_velocity;   // over the settling window; empty if not settled
  std::vector<Vec3> fragment_final_velocity;  // the mean velocity when settled, the last one otherwise
  Classification classification;
  // The largest fragment's velocity after the impact (its window mean when settled, its last one
  // otherwise) and its restitution: v_n after / |v_n| before.
  Vec3 rebound_velocity;
  double restitution_normal = 0.0;
  double restitution_tangential = 0.0;  // v_t after / v_t before along the impact's tangent; NaN head-on
  ClusterShape before;                  // the relaxed cluster
  ClusterShape after;                   // the largest fragment at the end
  SmallStrainCheck validity;

  // Energy
  EnergyBudget initial_energy;
  EnergyBudget final_energy;
  double fragment_translational_kinetic = 0.0;  // sum of 1/2 M_f v_f^2 at the end
};

// The result document (schemas/result.schema.json). Non-finite numbers are written as null.
nlohmann::ordered_json to_json(const ImpactResult& result);

// What an impact is set up to be, before it runs: time unit, time step, lambda, the energy
// groups, the contacts and the small-strain range, one line each (for `aerobreak impact`).
std::string describe_setup(const ImpactResult& prepared);

// Checks a result document against schemas/result.schema.json.
std::vector<SchemaViolation> validate_result(const nlohmann::ordered_json& document);

}  // namespace aerobreak
