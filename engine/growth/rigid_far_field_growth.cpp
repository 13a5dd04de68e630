#include "engine/growth/rigid_far_field_growth.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>

#include "engine/cluster/cluster_contacts.hpp"
#include "engine/core/disjoint_sets.hpp"
#include "engine/cluster/random_stream.hpp"
#include "engine/growth/cluster_proximity.hpp"

namespace aerobreak {
namespace {

// Largest mean square rotation per rigid step (rad^2 as 0.3^2): one rotation by the summed angle
// vector stands for the rotation's continuous path to second order in the angle.
constexpr double kMaxAngle = 0.3;

// SplitMix64 finaliser (Steele, Lea & Flood 2014): seeds of the rigid stream and the encounters.
std::uint64_t mix(std::uint64_t z) {
  z += 0x9e3779b97f4a7c15ULL;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}

// A cluster between encounters, with what its last encounter knew of its contacts.
struct FrozenCluster {
  RigidCluster body;
  std::size_t contacts = 0;
  std::size_t image_contacts = 0;
  double tension = 0.0;
};

struct Encounter {
  std::vector<std::size_t> members;  // particle index of each particle of the simulation
  std::unique_ptr<Simulation> simulation;
  std::uint64_t events = 0;             // contacts made and broken so far
  double quiet_since = 0.0;             // growth time of the last contact made or broken (or of the start)
  std::size_t clusters = 0;             // components of its contact graph
  std::vector<Vec3> searched_position;  // at the last gap search
};

// The search gap, shortened where the box is small: a pair must not reach half the box (one image).
double searchable_gap(const PeriodicBox& box, double wanted, double radius) {
  return std::min(wanted, 0.499 * box.shortest_edge() - 2.0 * radius);
}

std::uint64_t contact_events(const Simulation& s) { return s.pair_events().made + s.pair_events().broken; }

class Growth {
 public:
  Growth(const Particles& primaries, const Material& material, const ContactModelSpec& model,
         const SimulationSettings& base, const PrimaryBath& bath, const RigidFarFieldSettings& settings,
         std::uint64_t seed)
      : material_(material),
        model_(model),
        base_(base),
        bath_(bath),
        settings_(settings),
        seed_(seed),
        random_(mix(seed ^ 0x243f6a8885a308d3ULL)),
        box_(*base.periodic),
        proximity_(*base.periodic, searchable_gap(*base.periodic, settings.search_gap, bath.radius)),
        radius_(primaries.radius) {
    const Vec3 still;
    for (std::size_t i = 0; i < primaries.size(); ++i)
      frozen_.push_back({rigid_cluster({i}, {&primaries.position[i], 1}, {&still, 1}, {&still, 1}, bath), 0, 0, 0.0});
    free_primary_ = frozen_.front().body;
  }

  RigidFarFieldOutcome run(const std::function<void(const RigidFarFieldLook&)>& look) {
    std::size_t clusters = cluster_count();
    if (look) report(look);
    while (clusters > 1) {
      if (outcome_.rigid_steps >= settings_.max_steps)
        throw std::runtime_error("diffusion-limited aggregation: " + std::to_string(clusters) +
                                 " clusters remain after " + std::to_string(outcome_.rigid_steps) +
                                 " rigid steps; raise max_steps");
      advance();
      const std::size_t now = cluster_count();
      if (now != clusters && look) report(look);
      clusters = now;
    }
    finish();
    return std::move(outcome_);
  }

 private:
  // One step: hand close clusters to the engine, then move everything by the largest safe step.
  // The gaps come from a search only when the displacements since the last one may have eaten
  // half of a cluster's gap (Verlet 1967's skin, with the displacements actually taken): between
  // searches, clusters g and h are at least gap_g - moved_g - max_h moved_h apart.
  void advance() {
    if (searched_gap_.empty()) search();
    const double most = *std::max_element(moved_.begin(), moved_.end());
    double step = std::numeric_limits<double>::infinity();
    for (std::size_t g = 0; g < searched_gap_.size(); ++g) {
      const RigidCluster& c = g < frozen_.size() ? frozen_[g].body : free_primary_;
      const double gap = searched_gap_[g] - moved_[g] - most;
      step = std::min(step, step_for_reach(c, bath_.temperature, settings_.step_fraction * gap, kMaxAngle));
    }
    if (!encounters_.empty()) {
      const double dt = base_.time_step;
      const auto engine_steps = static_cast<std::int64_t>(
          std::clamp(std::floor(step / dt), 1.0, static_cast<double>(settings_.engine_chunk)));
      step = static_cast<double>(engine_steps) * dt;
      for (std::size_t e = 0; e < encounters_.size(); ++e) {
        Encounter& enc = encounters_[e];
        enc.simulation->run(engine_steps);
        outcome_.engine_particle_steps += engine_steps * static_cast<std::int64_t>(enc.members.size());
        const auto& x = enc.simulation->particles().position;
        double& moved = moved_[frozen_.size() + e];
        for (std::size_t k = 0; k < x.size(); ++k)
          moved = std::max(moved, norm(box_.minimum_image(x[k] - enc.searched_position[k])));
      }
    }
    for (std::size_t g = 0; g < frozen_.size(); ++g)
      moved_[g] += propagate(frozen_[g].body, step, bath_.temperature, random_);
    time_ += step;
    ++outcome_.rigid_steps;
    const std::size_t groups = frozen_.size() + encounters_.size();
    release_settled();
    const double farthest = *std::max_element(moved_.begin(), moved_.end());
    bool stale = groups != frozen_.size() + encounters_.size();
    for (std::size_t g = 0; g < searched_gap_.size() && !stale; ++g)
      stale = searched_gap_[g] - moved_[g] - farthest < 0.5 * searched_gap_[g];
    if (stale) searched_gap_.clear();
  }

  // Finds the gaps; clusters closer than the encounter gap become encounters first.
  void search() {
    GroupProximity near = proximity();
    for (std::size_t g = 0; g < frozen_.size(); ++g)
      if (near.gap[g] < 0.0) ++outcome_.overlaps;
    while (!near.close.empty()) {
      merge(near.close);
      near = proximity();
    }
    searched_gap_ = std::move(near.gap);
    moved_.assign(searched_gap_.size(), 0.0);
    for (Encounter& e : encounters_) e.searched_position = e.simulation->particles().position;
  }

  // Particle positions, groups (frozen clusters first, then encounters) and bounding spheres.
  GroupProximity proximity() {
    const std::size_t n = radius_.size();
    position_.resize(n);
    group_.resize(n);
    std::vector<BoundingSphere> spheres;
    for (std::size_t g = 0; g < frozen_.size(); ++g) {
      const RigidCluster& c = frozen_[g].body;
      const std::vector<Vec3> x = member_positions(c);
      for (std::size_t k = 0; k < c.members.size(); ++k) {
        position_[c.members[k]] = x[k];
        group_[c.members[k]] = static_cast<std::uint32_t>(g);
      }
      spheres.push_back({c.centre, c.reach});
    }
    for (std::size_t e = 0; e < encounters_.size(); ++e) {
      const Encounter& enc = encounters_[e];
      const auto& x = enc.simulation->particles().position;
      // Placed about the first member by nearest images; the sphere holds every placed centre,
      // which bounds the gap to any image of them.
      std::vector<Vec3> placed;
      Vec3 centre;
      for (std::size_t k = 0; k < x.size(); ++k) {
        placed.push_back(x[0] + box_.minimum_image(x[k] - x[0]));
        centre += placed.back();
        position_[enc.members[k]] = x[k];
        group_[enc.members[k]] = static_cast<std::uint32_t>(frozen_.size() + e);
      }
      centre = centre / static_cast<double>(x.size());
      double reach = 0.0;
      for (const Vec3& p : placed) reach = std::max(reach, norm(p - centre));
      spheres.push_back({centre, reach + bath_.radius});
    }
    return proximity_.find(position_, radius_, group_, frozen_.size() + encounters_.size(), spheres,
                           settings_.encounter_gap);
  }

  // Every set of groups linked by close pairs becomes one encounter.
  void merge(const std::vector<std::pair<std::uint32_t, std::uint32_t>>& close) {
    const std::size_t groups = frozen_.size() + encounters_.size();
    DisjointSets sets(groups);
    for (const auto& [a, b] : close) sets.unite(a, b);
    std::vector<FrozenCluster> frozen;
    std::vector<Encounter> encounters;
    std::vector<std::vector<std::size_t>> joined(groups);
    for (std::size_t g = 0; g < groups; ++g) joined[sets.find(g)].push_back(g);
    for (std::size_t g = 0; g < groups; ++g) {
      if (joined[g].size() == 1 && g < frozen_.size())
        frozen.push_back(std::move(frozen_[g]));
      else if (joined[g].size() == 1)
        encounters.push_back(std::move(encounters_[g - frozen_.size()]));
      else if (!joined[g].empty())
        encounters.push_back(encounter_of(joined[g]));
    }
    frozen_ = std::move(frozen);
    encounters_ = std::move(encounters);
  }

  Encounter encounter_of(const std::vector<std::size_t>& groups) {
    Encounter e;
    Particles p;
    const auto add = [&](std::size_t member, const Vec3& x, const Vec3& v, const Vec3& w) {
      e.members.push_back(member);
      p.add(x, bath_.radius, material_.density);
      p.velocity.back() = v;
      p.angular_velocity.back() = w;
    };
    for (std::size_t g : groups) {
      if (g < frozen_.size()) {
        const RigidCluster& c = frozen_[g].body;
        const std::vector<Vec3> x = member_positions(c), v = member_velocities(c);
        const Vec3 w = angular_velocity(c);
        for (std::size_t k = 0; k < c.members.size(); ++k) add(c.members[k], x[k], v[k], w);
      } else {
        const Encounter& old = encounters_[g - frozen_.size()];
        outcome_.contacts_broken += old.simulation->pair_events().broken;
        const Particles& q = old.simulation->particles();
        for (std::size_t k = 0; k < q.size(); ++k)
          add(old.members[k], q.position[k], q.velocity[k], q.angular_velocity[k]);
      }
    }
    SimulationSettings s = base_;
    s.body.langevin.seed = mix(seed_ ^ mix(++outcome_.encounters));
    e.simulation =
        std::make_unique<Simulation>(std::move(p), std::vector<Material>{material_}, std::vector<Wall>{}, model_, s);
    e.events = contact_events(*e.simulation);
    e.quiet_since = time_;
    e.clusters = connected_component_sizes(e.members.size(), contact_edges(*e.simulation)).size();
    return e;
  }

  // Encounters quiet for settle_time whose clusters are all release_gap apart become rigid again.
  void release_settled() {
    std::vector<Encounter> running;
    for (Encounter& e : encounters_) {
      const std::uint64_t events = contact_events(*e.simulation);
      if (events != e.events) {
        e.events = events;
        e.quiet_since = time_;
        e.clusters = connected_component_sizes(e.members.size(), contact_edges(*e.simulation)).size();
      }
      if (time_ - e.quiet_since >= settings_.settle_time && apart(e)) {
        freeze(e);
      } else {
        running.push_back(std::move(e));
      }
    }
    encounters_ = std::move(running);
  }

  bool apart(const Encounter& e) const {
    if (e.clusters == 1) return true;
    const Simulation& s = *e.simulation;
    std::vector<std::uint32_t> label(e.members.size());
    const std::vector<ContactCluster> parts = contact_clusters(s);
    for (std::size_t c = 0; c < parts.size(); ++c)
      for (std::size_t m : parts[c].members) label[m] = static_cast<std::uint32_t>(c);
    GroupProximitySearch search(box_, settings_.release_gap);
    return search.find(s.particles().position, s.particles().radius, label, parts.size(), {}, settings_.release_gap)
        .close.empty();
  }

  void freeze(const Encounter& e) {
    const Simulation& s = *e.simulation;
    outcome_.contacts_broken += s.pair_events().broken;
    const std::vector<double> tension = tension_per_particle(s);
    for (const ContactCluster& part : contact_clusters(s)) {
      std::vector<std::size_t> members;
      std::vector<Vec3> v, w;
      double most = 0.0;
      for (std::size_t m : part.members) {
        members.push_back(e.members[m]);
        v.push_back(s.particles().velocity[m]);
        w.push_back(s.particles().angular_velocity[m]);
        most = std::max(most, tension[m]);
      }
      frozen_.push_back(
          {rigid_cluster(std::move(members), part.position, v, w, bath_), part.contacts, part.image_contacts, most});
    }
  }

  static std::vector<double> tension_per_particle(const Simulation& s) {
    std::vector<double> tension(s.particles().size(), 0.0);
    s.contacts().for_each([&](const ContactState& c) {
      if (c.with_wall) return;
      tension[c.i] = std::max(tension[c.i], -c.overlap);
      tension[c.j] = std::max(tension[c.j], -c.overlap);
    });
    return tension;
  }

  std::size_t cluster_count() const {
    std::size_t n = frozen_.size();
    for (const Encounter& e : encounters_) n += e.clusters;
    return n;
  }

  std::vector<ContactCluster> clusters() const {
    std::vector<ContactCluster> all;
    for (const FrozenCluster& c : frozen_)
      all.push_back({c.body.members, member_positions(c.body), c.contacts, c.image_contacts});
    for (const Encounter& e : encounters_)
      for (ContactCluster part : contact_clusters(*e.simulation)) {
        for (std::size_t& m : part.members) m = e.members[m];
        all.push_back(std::move(part));
      }
    std::stable_sort(all.begin(), all.end(), [](const ContactCluster& a, const ContactCluster& b) {
      return a.members.size() > b.members.size();
    });
    return all;
  }

  void report(const std::function<void(const RigidFarFieldLook&)>& look) const {
    const std::vector<ContactCluster> all = clusters();
    look({outcome_.rigid_steps, time_, &all});
  }

  void finish() {
    outcome_.time = time_;
    if (!frozen_.empty()) {
      const FrozenCluster& c = frozen_.front();
      outcome_.grown = {c.body.members, member_positions(c.body), c.contacts, c.image_contacts};
      outcome_.tension = c.tension;
      return;
    }
    const Encounter& e = encounters_.front();
    outcome_.contacts_broken += e.simulation->pair_events().broken;
    outcome_.grown = contact_clusters(*e.simulation).front();
    for (std::size_t& m : outcome_.grown.members) m = e.members[m];
    const std::vector<double> tension = tension_per_particle(*e.simulation);
    outcome_.tension = *std::max_element(tension.begin(), tension.end());
  }

  Material material_;
  ContactModelSpec model_;
  SimulationSettings base_;
  PrimaryBath bath_;
  RigidFarFieldSettings settings_;
  std::uint64_t seed_;
  RandomStream random_;
  PeriodicBox box_;
  GroupProximitySearch proximity_;
  std::vector<double> radius_;
  std::vector<Vec3> position_;
  std::vector<std::uint32_t> group_;
  std::vector<FrozenCluster> frozen_;
  std::vector<Encounter> encounters_;
  RigidCluster free_primary_;
  std::vector<double> searched_gap_;  // per group, at the last search; empty: search next step
  std::vector<double> moved_;         // per group: farthest any member moved since
  double time_ = 0.0;
  RigidFarFieldOutcome outcome_;
};

}  // namespace

RigidFarFieldOutcome grow_with_rigid_far_field(const Particles& primaries, const Material& material,
                                               const ContactModelSpec& model, const SimulationSettings& base,
                                               const PrimaryBath& bath, const RigidFarFieldSettings& settings,
                                               std::uint64_t seed,
                                               const std::function<void(const RigidFarFieldLook&)>& look) {
  return Growth(primaries, material, model, base, bath, settings, seed).run(look);
}

}  // namespace aerobreak
