#include "engine/cluster/tunable_particle_cluster.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "engine/cluster/tunable_contact_circle.hpp"
#include "engine/cluster/tunable_free_arcs.hpp"
#include "engine/cluster/tunable_overlap_grid.hpp"
#include "engine/cluster/tunable_random_choice.hpp"

namespace aerobreak {
namespace {

// Free arcs shorter than this (radians) count as blocked: a monomer squeezed into such a sliver
// would sit within round-off of an overlap.
constexpr double min_free_arc = 1e-9;
// Not-yet-placed radii tried in turn for a step before it leaves the law.
constexpr std::size_t radii_tried_per_step = 8;
// Step of the search for the nearest usable distance, in units of the monomer radius: fine for
// the first steps, then growing so that the search reaches the aggregate's edge in O(sqrt) steps.
constexpr double distance_search_step = 0.02;
constexpr int fine_search_steps = 25;

std::string describe(double value) {
  std::ostringstream out;
  out.precision(4);
  out << value;
  return out.str();
}

// The aggregate grown so far, with the running sums that give its centre of mass and radius of
// gyration in O(1): Rg^2 = (sum m |x|^2 + sum m rg_own^2) / M - |c|^2 (FracVAL eqs. 4 and 5).
class GrowingAggregate {
 public:
  GrowingAggregate(double cell_edge, GyrationConvention convention) : grid_(cell_edge), convention_(convention) {}

  void add(const Vec3& x, double r) {
    const double m = r * r * r;
    grid_.insert(x, r);
    mass_ += m;
    first_ += m * x;
    second_ += m * norm2(x);
    own_ += m * primary_gyration_squared(r, convention_);
  }

  const TunableOverlapGrid& grid() const { return grid_; }
  std::size_t size() const { return grid_.size(); }
  double mass() const { return mass_; }
  Vec3 centre() const { return first_ / mass_; }
  double gyration_radius() const { return std::sqrt(std::max(0.0, (second_ + own_) / mass_ - norm2(centre()))); }

 private:
  TunableOverlapGrid grid_;
  GyrationConvention convention_;
  double mass_ = 0.0;
  Vec3 first_;
  double second_ = 0.0;
  double own_ = 0.0;
};

class MonomerPlacer {
 public:
  MonomerPlacer(const GrowingAggregate& aggregate, double max_radius, double overlap_tolerance, RandomStream& random)
      : aggregate_(aggregate),
        max_radius_(max_radius),
        overlap_tolerance_(overlap_tolerance),
        random_(random),
        centre_(aggregate.centre()) {}

  // Squared Gamma_pc (FracVAL eq. 6; Filippov et al. eq. 7 for equal primaries) that gives the
  // aggregate plus a monomer of radius r the radius of gyration `target`.
  double gamma_squared(double r, double target, GyrationConvention convention) const {
    return centre_distance_squared(aggregate_.mass(), aggregate_.gyration_radius(), r * r * r,
                                   std::sqrt(primary_gyration_squared(r, convention)), target);
  }

  // Farthest distance from the centre of mass at which a monomer of radius r can touch a primary.
  double farthest_reach(double r) const {
    double reach = 0.0;
    for (std::size_t i = 0; i < aggregate_.size(); ++i) {
      reach = std::max(reach, norm(grid().position(i) - centre_) + grid().radius(i) + r);
    }
    return reach;
  }

  // A uniformly drawn overlap-free position at distance gamma from the centre of mass touching a
  // primary, if there is one.
  std::optional<Vec3> touching_position(double r, double gamma) {
    std::vector<std::uint32_t> candidates;
    for (std::uint32_t i = 0; i < grid().size(); ++i) {
      const double d = norm(grid().position(i) - centre_);
      const double reach = grid().radius(i) + r;
      if (d > 0.0 && d >= std::abs(gamma - reach) && d <= gamma + reach) candidates.push_back(i);
    }
    shuffle(candidates, random_);
    std::vector<BlockedArc> blocked;
    for (std::uint32_t i : candidates) {
      const Vec3& x_i = grid().position(i);
      const double reach = grid().radius(i) + r;
      const std::optional<ContactCircle> circle = contact_circle(centre_, x_i, reach, gamma);
      if (!circle) continue;
      // Every point of the circle lies within `reach` of x_i, so only primaries within
      // reach + r + r_j of x_i can block it.
      blocked.clear();
      bool whole = false;
      grid().for_each_near(x_i, reach + r + max_radius_, [&](std::uint32_t j, const Vec3& x_j, double r_j) {
        if (j == i || whole) return;
        const double contact = (1.0 - overlap_tolerance_) * (r_j + r);
        if (const std::optional<BlockedArc> arc = blocked_arc(*circle, x_j, contact)) {
          whole = arc->half_width >= std::numbers::pi;
          blocked.push_back(*arc);
        }
      });
      if (whole) continue;
      if (const std::optional<double> angle = free_angle(blocked, random_.uniform(), min_free_arc)) {
        return circle->at(*angle);
      }
    }
    return std::nullopt;
  }

  // Straight outward of the primary i reaching farthest (largest |x_i - c| + r_i): no primary j
  // can overlap it there, since |x_j - c| + r_j <= |x_i - c| + r_i.
  Vec3 outermost_position(double r) const {
    std::size_t best = 0;
    double best_reach = -1.0;
    for (std::size_t i = 0; i < aggregate_.size(); ++i) {
      const double reach = norm(grid().position(i) - centre_) + grid().radius(i);
      if (reach > best_reach) {
        best_reach = reach;
        best = i;
      }
    }
    const Vec3 arm = grid().position(best) - centre_;
    return grid().position(best) + (grid().radius(best) + r) * (arm / norm(arm));
  }

 private:
  const TunableOverlapGrid& grid() const { return aggregate_.grid(); }

  const GrowingAggregate& aggregate_;
  double max_radius_;
  double overlap_tolerance_;
  RandomStream& random_;
  Vec3 centre_;
};

// Puts the radii in the order of growth and returns the law's primary radius a, the geometric
// mean of all the primaries to be placed (FracVAL's choice for this stage): the final aggregate
// then obeys the law with its own a. The radius nearest to a is kept for the last step, where no
// other radius can stand in, so that the final monomer behaves as in a monodisperse aggregate;
// the starting dimer is made of the next two nearest, so that its fixed Rg is typical.
double arrange_radii(std::vector<double>& radii) {
  const std::size_t n = radii.size();
  double log_mean = 0.0;
  for (double r : radii) log_mean += std::log(r);
  log_mean /= static_cast<double>(n);
  const auto nearer_to_mean = [&](double x, double y) {
    return std::abs(std::log(x) - log_mean) < std::abs(std::log(y) - log_mean);
  };
  const auto last = radii.end() - 1;
  std::iter_swap(std::min_element(radii.begin(), radii.end(), nearer_to_mean), last);
  for (std::size_t k = 0; k < 2 && k + 1 < n; ++k) {
    const auto slot = radii.begin() + static_cast<std::ptrdiff_t>(k);
    std::iter_swap(slot, std::min_element(slot, last, nearer_to_mean));
  }
  return std::exp(log_mean);
}

// Why step k (growing to k + 1 primaries) found no position on the law at Gamma_pc^2 = gamma2.
std::string off_law_reason(std::size_t k, double gamma2, double farthest) {
  const double gamma = std::sqrt(std::max(0.0, gamma2));
  const std::string step =
      "growing the aggregate from " + std::to_string(k) + " to " + std::to_string(k + 1) + " primaries, ";
  if (!(gamma2 > 0.0)) return step + "Gamma_pc^2 = " + describe(gamma2) + " <= 0 (too compact)";
  if (gamma > farthest)
    return step + "Gamma_pc = " + describe(gamma) + " is beyond the reach of every primary, at most " +
           describe(farthest) + " (too open)";
  return step + "no position at distance Gamma_pc = " + describe(gamma) +
         " touches a primary without overlapping another (too compact)";
}

// Off the law: the position at the nearest distance beyond gamma that has one, else straight
// outward of the outermost primary.
Vec3 nearest_off_law_position(MonomerPlacer& placer, double r, double gamma, double farthest) {
  std::optional<Vec3> position;
  for (int i = 1; !position; ++i) {
    const double g = gamma + distance_search_step * r * (i <= fine_search_steps ? i : i * (i - fine_search_steps));
    if (g >= farthest) break;
    position = placer.touching_position(r, g);
  }
  return position ? *position : placer.outermost_position(r);
}

}  // namespace

ParticleClusterGrowth grow_particle_cluster(std::vector<double> radii, const FractalLaw& law,
                                            const ParticleClusterSettings& settings, RandomStream& random) {
  const std::size_t n = radii.size();
  const double max_radius = *std::max_element(radii.begin(), radii.end());
  const double a = arrange_radii(radii);

  GrowingAggregate aggregate(2.0 * max_radius, law.convention);
  aggregate.add(Vec3{}, radii[0]);
  if (n >= 2) aggregate.add((radii[0] + radii[1]) * random.unit_vector(), radii[1]);

  ParticleClusterGrowth growth;
  for (std::size_t k = 2; k < n; ++k) {
    const double target = law.gyration_radius(static_cast<double>(k + 1), a);
    MonomerPlacer placer(aggregate, max_radius, settings.overlap_tolerance, random);

    // On the law: the first of the next few not-yet-placed radii (FracVAL's swap) that has a
    // position; the reserved one only in the last step.
    const std::size_t window_end = k + 1 == n ? n : std::min(n - 1, k + radii_tried_per_step);
    std::vector<double> tried;
    std::optional<Vec3> position;
    for (std::size_t s = k; s < window_end && !position; ++s) {
      if (std::find(tried.begin(), tried.end(), radii[s]) != tried.end()) continue;
      tried.push_back(radii[s]);
      const double gamma2 = placer.gamma_squared(radii[s], target, law.convention);
      if (gamma2 > 0.0) position = placer.touching_position(radii[s], std::sqrt(gamma2));
      if (position) std::swap(radii[k], radii[s]);
    }
    if (position) {
      aggregate.add(*position, radii[k]);
      continue;
    }

    // Off the law: the nearest distance that has a position.
    const double r = radii[k];
    const double gamma2 = placer.gamma_squared(r, target, law.convention);
    const double farthest = placer.farthest_reach(r);
    std::string shortfall = off_law_reason(k, gamma2, farthest);
    aggregate.add(nearest_off_law_position(placer, r, std::sqrt(std::max(0.0, gamma2)), farthest), r);

    const double deviation = std::abs(aggregate.gyration_radius() / target - 1.0);
    shortfall += "; the nearest reachable aggregate has Rg = " + describe(aggregate.gyration_radius()) +
                 " where the law asks for " + describe(target);
    if (k + 1 > settings.deviation_tracked_above && deviation > settings.max_deviation) {
      growth.failure = shortfall + " (" + describe(100.0 * deviation) + "% off, tolerated " +
                       describe(100.0 * settings.max_deviation) + "%)";
      return growth;
    }
    if (k + 1 == n) growth.last_step_shortfall = std::move(shortfall);
  }

  std::vector<Vec3> positions;
  positions.reserve(n);
  for (std::size_t i = 0; i < n; ++i) positions.push_back(aggregate.grid().position(i));
  growth.aggregate = centred_aggregate(std::move(positions), std::move(radii), law.convention);
  return growth;
}

}  // namespace aerobreak
