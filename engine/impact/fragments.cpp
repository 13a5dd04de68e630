#include "engine/impact/fragments.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>

#include "engine/core/disjoint_sets.hpp"
#include "engine/dem/simulation.hpp"

namespace aerobreak {

FragmentAnalysis find_fragments(const Particles& p,
                                const std::vector<std::pair<std::uint32_t, std::uint32_t>>& contacts,
                                const std::vector<std::uint32_t>& wall_contacts_per_particle, const Wall& wall) {
  const std::size_t n = p.size();
  DisjointSets sets(n);
  for (const auto& [i, j] : contacts) sets.unite(i, j);

  // Number the components in order of their lowest particle index.
  std::vector<std::uint32_t> component(n, std::numeric_limits<std::uint32_t>::max());
  std::vector<std::uint32_t> root_label(n, std::numeric_limits<std::uint32_t>::max());
  std::vector<Fragment> found;
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::size_t root = sets.find(i);
    if (root_label[root] == std::numeric_limits<std::uint32_t>::max()) {
      root_label[root] = static_cast<std::uint32_t>(found.size());
      Fragment f;
      f.first_primary = i;
      f.lowest_gap = std::numeric_limits<double>::infinity();
      found.push_back(f);
    }
    component[i] = root_label[root];
  }

  const Vec3 normal = wall.normal / norm(wall.normal);
  for (std::size_t i = 0; i < n; ++i) {
    Fragment& f = found[component[i]];
    f.size += 1;
    f.mass += p.mass[i];
    f.centre_of_mass += p.mass[i] * p.position[i];
    f.velocity += p.mass[i] * p.velocity[i];
    if (!wall_contacts_per_particle.empty()) f.wall_contacts += wall_contacts_per_particle[i];
    f.lowest_gap = std::min(f.lowest_gap, dot(p.position[i] - wall.point, normal) - p.radius[i]);
  }
  for (Fragment& f : found) {
    f.centre_of_mass = f.centre_of_mass / f.mass;
    f.velocity = f.velocity / f.mass;
    f.normal_velocity = dot(f.velocity, normal);
  }
  for (std::size_t i = 0; i < n; ++i) {
    Fragment& f = found[component[i]];
    const Vec3 r = p.position[i] - f.centre_of_mass;
    f.radius_of_gyration += p.mass[i] * norm2(r);
    f.bounding_radius = std::max(f.bounding_radius, norm(r) + p.radius[i]);
  }
  for (Fragment& f : found) f.radius_of_gyration = std::sqrt(f.radius_of_gyration / f.mass);

  std::vector<std::uint32_t> order(found.size());
  std::iota(order.begin(), order.end(), 0u);
  std::sort(order.begin(), order.end(), [&](std::uint32_t a, std::uint32_t b) {
    if (found[a].size != found[b].size) return found[a].size > found[b].size;
    if (found[a].mass != found[b].mass) return found[a].mass > found[b].mass;
    return found[a].first_primary < found[b].first_primary;
  });
  std::vector<std::uint32_t> rank(found.size());
  FragmentAnalysis result;
  result.fragments.reserve(found.size());
  for (std::uint32_t k = 0; k < order.size(); ++k) {
    rank[order[k]] = k;
    result.fragments.push_back(found[order[k]]);
  }
  result.fragment_of.resize(n);
  for (std::size_t i = 0; i < n; ++i) result.fragment_of[i] = rank[component[i]];
  return result;
}

FragmentAnalysis find_fragments(const Simulation& simulation, std::size_t wall_index) {
  const Particles& p = simulation.particles();
  std::vector<std::pair<std::uint32_t, std::uint32_t>> contacts;
  contacts.reserve(simulation.contacts().size());
  std::vector<std::uint32_t> on_wall(p.size(), 0);
  simulation.contacts().for_each([&](const ContactState& c) {
    if (!c.with_wall)
      contacts.emplace_back(c.i, c.j);
    else if (c.j == wall_index)
      on_wall[c.i] += 1;
  });
  const Wall wall = simulation.walls().empty() ? Wall{} : simulation.walls()[wall_index];
  return find_fragments(p, contacts, on_wall, wall);
}

std::vector<FragmentFate> fates_of(const std::vector<Fragment>& fragments, const std::vector<Vec3>& velocity,
                                   const Vec3& wall_normal) {
  const Vec3 n = wall_normal / norm(wall_normal);
  std::vector<FragmentFate> fates(fragments.size());
  for (std::size_t k = 0; k < fragments.size(); ++k)
    fates[k] = {fragments[k].size, fragments[k].mass, fragments[k].on_wall(), dot(velocity[k], n), norm(velocity[k])};
  return fates;
}

std::vector<std::pair<std::size_t, std::size_t>> size_distribution(const std::vector<Fragment>& fragments) {
  std::map<std::size_t, std::size_t> counts;
  for (const Fragment& f : fragments) counts[f.size] += 1;
  return {counts.begin(), counts.end()};
}

}  // namespace aerobreak
