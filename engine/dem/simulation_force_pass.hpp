#pragma once
// The force pass of one step, shared by Simulation's plain step (simulation.cpp) and its
// wavefronts (wavefront.cpp). Internal to aerobreak_dem.
#include <cstdint>
#include <vector>

#include "engine/dem/contact_forces.hpp"
#include "engine/dem/simulation.hpp"

namespace aerobreak {

// What follows a particle's last pair force in a force pass: its wall contacts; then, unless
// van der Waals forces are still to come, its body forces and, when the run goes on, the kicks
// and the drift of the next step. Its sums run over the particles in index order, across the
// ranges the pair loop reports, exactly as separate passes over all particles would.
class Simulation::ForcePass final : public ParticleCompletion {
 public:
  ForcePass(Simulation& simulation, bool finish, bool integrate, std::int64_t step)
      : sim_(simulation), finish_(finish), integrate_(integrate), step_(step), wall_tally_(simulation.walls_.size()) {}

  void complete(std::size_t begin, std::size_t end) override;

  // What the pass adds to the run's sums, in the order one pass at a time adds it.
  void book(DissipationTally& tally, double& external_work) const {
    for (const DissipationTally& wall : wall_tally_) tally += wall;
    if (finish_) external_work += body_work_;
  }
  const ParticleDrift& drift() const { return drift_; }

 private:
  Simulation& sim_;
  bool finish_;
  bool integrate_;
  std::int64_t step_;
  std::vector<DissipationTally> wall_tally_;  // each wall's dissipation in this pass
  double body_work_ = 0.0;
  ParticleDrift drift_;
};

}  // namespace aerobreak
