#pragma once
#include <algorithm>

namespace aerobreak {

// How far the particles have drifted: the largest squared displacement of a particle since the
// neighbour list was built, and in the last drift of a step. The first decides when the list
// must be rebuilt (Verlet skin), the second how deep a wavefront may go (wavefront.hpp). With a
// step chosen from the speeds of the moment (step_chooser.hpp), also the largest squared
// departure of a drift velocity from the one it had when the step was chosen.
struct ParticleDrift {
  double since_build2 = 0.0;
  double last_step2 = 0.0;
  double departure2 = 0.0;
  void merge(const ParticleDrift& other) {
    since_build2 = std::max(since_build2, other.since_build2);
    last_step2 = std::max(last_step2, other.last_step2);
    departure2 = std::max(departure2, other.departure2);
  }
};

}  // namespace aerobreak
