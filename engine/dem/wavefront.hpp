#pragma once
#include <cstdint>
#include <limits>
#include <optional>
#include <vector>

#include "engine/core/vec3.hpp"
#include "engine/dem/contact_forces.hpp"
#include "engine/dem/contact_pool.hpp"
#include "engine/dem/particle_drift.hpp"

namespace aerobreak {

class Simulation;

// Several consecutive steps whose force passes run together as a wavefront over the particles
// (ContactForces::add_pair_forces; docs/MODEL.md 9.1, docs/PERFORMANCE.md "Large clusters"): for a
// system too large for the caches each particle's arrays are fetched once for several steps. The
// results are those of the steps one at a time, to the last bit. This part of a Simulation
// decides how deep a wavefront may go, runs it, and undoes it from a checkpoint when a particle
// has left the neighbour list's skin during it; Simulation::run itself is plain velocity Verlet.
class Wavefront {
 public:
  struct Settings {
    int depth = 16;                     // deepest wavefront; 1: one step at a time
    std::size_t min_particles = 24000;  // fewer particles: one step at a time
    double margin = 2.0;                // a step moves a particle at most this many times the last step's farthest
  };
  explicit Wavefront(Settings settings) : settings_(settings) {}

  // At the start of every Simulation::run.
  void begin_run() { one_by_one_left_ = std::numeric_limits<std::int64_t>::max(); }
  // With at most `left` steps of a run to go, and the run to stop at the clock `until`: runs the
  // next steps as one wavefront where it can and returns how many it ran (0: none, the caller
  // takes one plain step). It may rebuild the neighbour list and choose the step first (as the
  // plain step would); `drift` follows the particles either way.
  std::int64_t advance(Simulation& sim, ParticleDrift& drift, std::int64_t left, double until);

  std::uint64_t steps() const { return steps_; }    // steps run in wavefronts
  std::uint64_t undone() const { return undone_; }  // wavefronts undone (their steps ran one at a time)

 private:
  // What a wavefront changes, to undo it (forces are zero between passes).
  struct Checkpoint {
    std::vector<Vec3> position, velocity, angular_velocity;
    ContactPool pair_pool{false};
    ContactPool wall_pool{true};
    std::vector<std::vector<std::int32_t>> wall_slots;
    std::vector<std::int32_t> pair_contacts;
    ContactEvents pair_events, wall_events;
  };
  std::int64_t deepest(const Simulation& sim) const;
  std::int64_t room(const Simulation& sim, double since_build2, const ParticleDrift& drift, std::int64_t wanted) const;
  std::optional<ParticleDrift> run(Simulation& sim, int depth, bool integrate_last);
  void save(const Simulation& sim);
  void restore(Simulation& sim) const;

  Settings settings_;
  Checkpoint checkpoint_;
  std::uint64_t steps_ = 0;
  std::uint64_t undone_ = 0;
  // Deepest wavefront to try next: halved when one is undone, doubled again after one that is not.
  std::int64_t cap_ = std::numeric_limits<std::int32_t>::max();
  // After a wavefront that was undone, its steps one at a time: while more than this many steps of
  // the run are left.
  std::int64_t one_by_one_left_ = std::numeric_limits<std::int64_t>::max();
};

}  // namespace aerobreak
