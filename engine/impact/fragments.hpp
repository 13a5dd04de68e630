#pragma once
#include <cstddef>
#include <cstdint>
#include <utility>
#include <vector>

#include "engine/core/particles.hpp"
#include "engine/core/vec3.hpp"
#include "engine/dem/wall.hpp"
#include "engine/impact/outcome.hpp"

namespace aerobreak {

class Simulation;

// One fragment: a connected component of the particle-particle contact graph (docs/IMPACT.md
// section 5); a primary without contacts is a fragment of size 1.
struct Fragment {
  std::size_t size = 0;  // primaries
  double mass = 0.0;
  Vec3 centre_of_mass;
  Vec3 velocity;                    // of the centre of mass
  double normal_velocity = 0.0;     // velocity . wall normal (> 0: moving away from the wall)
  std::size_t wall_contacts = 0;    // live contacts of its primaries with the wall
  double lowest_gap = 0.0;          // smallest surface gap of its primaries to the wall (< 0: overlapping)
  double radius_of_gyration = 0.0;  // of the primaries' centres, mass-weighted
  double bounding_radius = 0.0;     // largest |x_i - x_cm| + r_i
  std::uint32_t first_primary = 0;  // lowest particle index in it (a stable name)
  // Fates foreseen by the fates-fixed rule (docs/IMPACT.md section 4): off the wall now, it lands
  // on an adhesive wall and stays there (counted on the wall), or it bounces (or, several primaries
  // unable to break, may bounce) off a wall without adhesion (counted off it).
  bool landing = false;
  bool bouncing = false;

  // Touches the wall, or lands on it and stays.
  bool on_wall() const { return wall_contacts > 0 || landing; }
};

struct FragmentAnalysis {
  std::vector<Fragment> fragments;         // largest first (then heavier, then lower first_primary)
  std::vector<std::uint32_t> fragment_of;  // per particle: index into fragments
};

// Fragments of `particles` given their particle-particle contacts (pairs of indices) and the
// number of wall contacts of each particle (empty: none).
FragmentAnalysis find_fragments(const Particles& particles,
                                const std::vector<std::pair<std::uint32_t, std::uint32_t>>& contacts,
                                const std::vector<std::uint32_t>& wall_contacts_per_particle, const Wall& wall);

// Fragments of a running simulation from its live contacts; wall contacts are those with
// `wall_index`.
FragmentAnalysis find_fragments(const Simulation& simulation, std::size_t wall_index = 0);

// What the outcome rule reads of each fragment, with `velocity[k]` taken as fragment k's
// centre-of-mass velocity (the window mean of a settled state, or the instantaneous one).
std::vector<FragmentFate> fates_of(const std::vector<Fragment>& fragments, const std::vector<Vec3>& velocity,
                                   const Vec3& wall_normal);

// Number of fragments of each size, ascending in size: (size, count).
std::vector<std::pair<std::size_t, std::size_t>> size_distribution(const std::vector<Fragment>& fragments);

}  // namespace aerobreak
