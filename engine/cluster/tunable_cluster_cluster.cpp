#include "engine/cluster/tunable_cluster_cluster.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "engine/cluster/rotation.hpp"
#include "engine/cluster/tunable_overlap_grid.hpp"
#include "engine/cluster/tunable_random_choice.hpp"

namespace aerobreak {
namespace {

// Largest relative error in the contact distance of the joining pair accepted from round-off
// (measured: below 1e-12 up to N = 4096).
constexpr double contact_tolerance = 1e-10;

std::string describe(double value) {
  std::ostringstream out;
  out.precision(4);
  out << value;
  return out.str();
}

// Two unit vectors completing the unit vector w to a right-handed orthonormal frame (w, u, v).
std::pair<Vec3, Vec3> perpendicular_pair(const Vec3& w) {
  const Vec3 helper = std::abs(w.x) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
  Vec3 u = cross(w, helper);
  u = u / norm(u);
  return {u, cross(w, u)};
}

// A point at distance `radius` from `centre` in direction (cos_polar w + sin_polar (cos azimuth u +
// sin azimuth v)), (w, u, v) the frame of axis w.
Vec3 point_about(const Vec3& centre, const Vec3& w, double radius, double cos_polar, double azimuth) {
  const auto [u, v] = perpendicular_pair(w);
  const double sin_polar = std::sqrt(std::max(0.0, 1.0 - cos_polar * cos_polar));
  return centre + radius * (cos_polar * w + sin_polar * (std::cos(azimuth) * u + std::sin(azimuth) * v));
}

// The rotation taking unit vector `from` to unit vector `to`, turned by `twist` about `to`: maps
// the frame (from, p, q) onto (to, p', q'), i.e. R = T B^T with those frames as columns.
Rotation rotation_taking(const Vec3& from, const Vec3& to, double twist) {
  const auto [p, q] = perpendicular_pair(from);
  const auto [a, b] = perpendicular_pair(to);
  const Vec3 p2 = std::cos(twist) * a + std::sin(twist) * b;
  const Vec3 q2 = cross(to, p2);
  return {to.x * from + p2.x * p + q2.x * q, to.y * from + p2.y * p + q2.y * q, to.z * from + p2.z * p + q2.z * q};
}

// Each of four lengths at most the sum of the other three: a (possibly degenerate) quadrilateral
// c_a - x_i - x_j - c_b exists.
bool closes(double gamma, double d, double contact, double e) {
  const double total = gamma + d + contact + e;
  return 2.0 * std::max({gamma, d, contact, e}) <= total;
}

// Admissible partners: for each primary i of a, the range [begin, end) of b's primaries (sorted by
// distance e from c_b) whose e can close the quadrilateral with some contact distance
// r_i + r_j <= r_i + max r_b; the exact test with r_j follows when a pair is drawn.
struct PairCandidates {
  std::vector<std::pair<double, std::uint32_t>> partners;  // (e_j, j), ascending
  std::vector<std::size_t> begin, end;
  std::vector<std::size_t> cumulative;  // cumulative[i] = sum of range sizes of primaries < = i
  std::size_t total = 0;
};

PairCandidates pair_candidates(const TunableAggregate& a, const TunableAggregate& b, double gamma) {
  PairCandidates c;
  c.partners.reserve(b.size());
  double max_radius_b = 0.0;
  for (std::size_t j = 0; j < b.size(); ++j) {
    c.partners.emplace_back(norm(b.position[j]), static_cast<std::uint32_t>(j));
    max_radius_b = std::max(max_radius_b, b.radius[j]);
  }
  std::sort(c.partners.begin(), c.partners.end());
  const auto by_distance = [](const std::pair<double, std::uint32_t>& p, double e) { return p.first < e; };
  c.begin.resize(a.size());
  c.end.resize(a.size());
  c.cumulative.resize(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = norm(a.position[i]);
    const double longest_contact = a.radius[i] + max_radius_b;
    const double lowest = std::abs(gamma - d) - longest_contact;
    const double highest = gamma + d + longest_contact;
    c.begin[i] = static_cast<std::size_t>(std::lower_bound(c.partners.begin(), c.partners.end(), lowest, by_distance) -
                                          c.partners.begin());
    c.end[i] = static_cast<std::size_t>(
        std::lower_bound(c.partners.begin(), c.partners.end(), std::nextafter(highest, 1e300), by_distance) -
        c.partners.begin());
    c.total += c.end[i] - c.begin[i];
    c.cumulative[i] = c.total;
  }
  return c;
}

// One trial configuration: b's rotation and centre of mass, with x_i of a touching x_j of b.
struct Trial {
  Rotation orientation;
  Vec3 centre;
};

std::optional<Trial> trial_configuration(const Vec3& x_i, double contact, const Vec3& body_j, double gamma,
                                         RandomStream& random) {
  const double d = norm(x_i);
  const double e = norm(body_j);
  // Contact point of x_j: on the sphere of radius `contact` about x_i, where its distance s from
  // c_a (the origin) lets c_b lie at gamma from c_a and e from x_j: |gamma - e| <= s <= gamma + e.
  // On that sphere s^2 = d^2 + contact^2 + 2 d contact cos(polar about x_i's direction), and the
  // area is uniform in cos(polar) (Archimedes), so cos(polar) is drawn uniformly on its interval.
  Vec3 contact_point;
  if (d > 0.0) {
    const double low = std::abs(gamma - e);
    const double high = gamma + e;
    const double lo = std::max(-1.0, (low * low - d * d - contact * contact) / (2.0 * d * contact));
    const double hi = std::min(1.0, (high * high - d * d - contact * contact) / (2.0 * d * contact));
    if (lo > hi) return std::nullopt;
    const double cos_polar = lo + (hi - lo) * random.uniform();
    contact_point = point_about(x_i, x_i / d, contact, cos_polar, 2.0 * std::numbers::pi * random.uniform());
  } else {
    contact_point = x_i + contact * random.unit_vector();
  }

  // c_b on the circle where the sphere |c| = gamma meets the sphere |c - contact_point| = e.
  const double s = norm(contact_point);
  Vec3 centre;
  if (s > 0.0) {
    const double along = (gamma * gamma - e * e + s * s) / (2.0 * s);
    const double cos_polar = std::clamp(along / gamma, -1.0, 1.0);
    centre = point_about(Vec3{}, contact_point / s, gamma, cos_polar, 2.0 * std::numbers::pi * random.uniform());
  } else {
    centre = gamma * random.unit_vector();
  }

  const Vec3 arm = contact_point - centre;
  const double arm_length = norm(arm);
  if (!(e > 0.0) || !(arm_length > 0.0)) return Trial{random.rotation(), centre};
  return Trial{rotation_taking(body_j / e, arm / arm_length, 2.0 * std::numbers::pi * random.uniform()), centre};
}

}  // namespace

TunableJoin join_aggregates(const TunableAggregate& a, const TunableAggregate& b, const FractalLaw& law,
                            int max_attempts, double overlap_tolerance, RandomStream& random) {
  const std::size_t n = a.size() + b.size();
  const std::string stage =
      "joining aggregates of " + std::to_string(a.size()) + " and " + std::to_string(b.size()) + " primaries: ";
  const double target = law.gyration_radius(static_cast<double>(n),
                                            std::exp((a.log_radius_sum + b.log_radius_sum) / static_cast<double>(n)));
  // Gamma_cc from FracVAL eq. 6.
  const double gamma2 = centre_distance_squared(a.mass, a.gyration_radius, b.mass, b.gyration_radius, target);
  if (!(gamma2 > 0.0)) {
    return {std::nullopt, stage + "Gamma_cc^2 = " + describe(gamma2) + " <= 0: the target Rg = " + describe(target) +
                              " is below what any placement of the two gives (too compact)"};
  }
  const double gamma = std::sqrt(gamma2);

  const PairCandidates candidates = pair_candidates(a, b, gamma);
  if (candidates.total == 0) {
    return {std::nullopt,
            stage + "Gamma_cc = " + describe(gamma) + " is beyond the reach of every pair of primaries (too open)"};
  }

  double max_radius = 0.0;
  for (double r : a.radius) max_radius = std::max(max_radius, r);
  for (double r : b.radius) max_radius = std::max(max_radius, r);
  TunableOverlapGrid grid(2.0 * max_radius);
  for (std::size_t i = 0; i < a.size(); ++i) grid.insert(a.position[i], a.radius[i]);
  std::vector<Vec3> placed(b.size());
  for (int attempt = 0; attempt < max_attempts; ++attempt) {
    const std::size_t pick = uniform_index(random, candidates.total);
    const std::size_t i =
        static_cast<std::size_t>(std::upper_bound(candidates.cumulative.begin(), candidates.cumulative.end(), pick) -
                                 candidates.cumulative.begin());
    const std::size_t before = candidates.cumulative[i] - (candidates.end[i] - candidates.begin[i]);
    const std::size_t j = candidates.partners[candidates.begin[i] + (pick - before)].second;
    const double contact = a.radius[i] + b.radius[j];
    if (!closes(gamma, norm(a.position[i]), contact, norm(b.position[j]))) continue;

    const std::optional<Trial> trial = trial_configuration(a.position[i], contact, b.position[j], gamma, random);
    if (!trial) continue;
    // At the edge of the admissible range the circle of c_b shrinks to a point and round-off can
    // leave x_j off the contact; such a trial is dropped.
    const Vec3 x_j = trial->centre + trial->orientation.apply(b.position[j]);
    if (std::abs(norm(x_j - a.position[i]) / contact - 1.0) > contact_tolerance) continue;
    bool clear = true;
    for (std::size_t k = 0; k < b.size() && clear; ++k) {
      placed[k] = trial->centre + trial->orientation.apply(b.position[k]);
      clear = !grid.overlaps(placed[k], b.radius[k], overlap_tolerance);
    }
    if (!clear) continue;

    std::vector<Vec3> position = a.position;
    position.insert(position.end(), placed.begin(), placed.end());
    std::vector<double> radius = a.radius;
    radius.insert(radius.end(), b.radius.begin(), b.radius.end());
    return {centred_aggregate(std::move(position), std::move(radius), law.convention), ""};
  }
  return {std::nullopt, stage + "no orientation with the centres of mass Gamma_cc = " + describe(gamma) +
                            " apart touches without overlap after " + std::to_string(max_attempts) +
                            " attempts (too compact)"};
}

}  // namespace aerobreak
