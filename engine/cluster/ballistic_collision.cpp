#include "engine/cluster/ballistic_collision.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>
#include <vector>

namespace aerobreak {

FlightFrame flight_frame(const Vec3& u) {
  const Vec3 helper = std::abs(u.x) < 0.9 ? Vec3{1.0, 0.0, 0.0} : Vec3{0.0, 1.0, 0.0};
  const Vec3 c = cross(u, helper);
  const Vec3 e1 = c / norm(c);
  return {e1, cross(u, e1), u};
}

namespace {

// A target primary in flight-frame coordinates: (a, b) in the normal plane, `along` the flight.
struct ProjectedPrimary {
  double a, b, along, radius;
};

// The target's primaries binned by their projection onto the normal plane (counting sort into
// contiguous cells): each cell is a column along the flight direction.
class ColumnGrid {
 public:
  ColumnGrid(const Cluster& target, const FlightFrame& frame, double min_cell_size) {
    std::vector<ProjectedPrimary> projected(target.size());
    double a_max = -std::numeric_limits<double>::infinity();
    double b_max = a_max;
    a0_ = b0_ = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < target.size(); ++i) {
      const Vec3& x = target.position[i];
      projected[i] = {dot(x, frame.e1), dot(x, frame.e2), dot(x, frame.u), target.radius[i]};
      a0_ = std::min(a0_, projected[i].a);
      b0_ = std::min(b0_, projected[i].b);
      a_max = std::max(a_max, projected[i].a);
      b_max = std::max(b_max, projected[i].b);
    }
    // Cells no smaller than the contact reach, and no more than about four per primary.
    const double area_per_cell = (a_max - a0_) * (b_max - b0_) / (4.0 * target.size() + 16.0);
    cell_ = std::max(min_cell_size, std::sqrt(area_per_cell));
    na_ = static_cast<long>((a_max - a0_) / cell_) + 1;
    nb_ = static_cast<long>((b_max - b0_) / cell_) + 1;

    std::vector<std::size_t> cell_of(projected.size());
    start_.assign(static_cast<std::size_t>(na_ * nb_) + 1, 0);
    for (std::size_t i = 0; i < projected.size(); ++i) {
      cell_of[i] = cell_index(index_along(projected[i].a, a0_), index_along(projected[i].b, b0_));
      ++start_[cell_of[i] + 1];
    }
    for (std::size_t c = 1; c < start_.size(); ++c) start_[c] += start_[c - 1];
    items_.resize(projected.size());
    std::vector<std::size_t> fill(start_.begin(), start_.end() - 1);
    for (std::size_t i = 0; i < projected.size(); ++i) items_[fill[cell_of[i]]++] = projected[i];
  }

  // Calls visit(primary) for every target primary in the 3x3 columns around point (a, b).
  template <class Visit>
  void for_each_near(double a, double b, Visit&& visit) const {
    const long ia = clamped_index(a, a0_, na_);
    const long ib = clamped_index(b, b0_, nb_);
    for (long ja = std::max(0L, ia - 1); ja <= std::min(na_ - 1, ia + 1); ++ja) {
      for (long jb = std::max(0L, ib - 1); jb <= std::min(nb_ - 1, ib + 1); ++jb) {
        const std::size_t c = cell_index(ja, jb);
        for (std::size_t k = start_[c]; k < start_[c + 1]; ++k) visit(items_[k]);
      }
    }
  }

 private:
  long index_along(double coordinate, double origin) const { return static_cast<long>((coordinate - origin) / cell_); }
  // Cell index of a query point, clamped just outside the grid so that far points visit nothing.
  long clamped_index(double coordinate, double origin, long count) const {
    const double cells = std::floor((coordinate - origin) / cell_);
    return static_cast<long>(std::clamp(cells, -2.0, static_cast<double>(count + 1)));
  }
  std::size_t cell_index(long ia, long ib) const { return static_cast<std::size_t>(ia * nb_ + ib); }

  double a0_, b0_, cell_;
  long na_, nb_;
  std::vector<std::size_t> start_;
  std::vector<ProjectedPrimary> items_;
};

double largest_radius(const Cluster& cluster) {
  return *std::max_element(cluster.radius.begin(), cluster.radius.end());
}

}  // namespace

std::optional<double> first_contact_travel(const Cluster& target, const Cluster& projectile, const Vec3& direction) {
  if (target.size() == 0 || projectile.size() == 0) return std::nullopt;
  const FlightFrame frame = flight_frame(direction);
  const ColumnGrid grid(target, frame, largest_radius(target) + largest_radius(projectile));

  double first = std::numeric_limits<double>::infinity();
  for (std::size_t j = 0; j < projectile.size(); ++j) {
    const Vec3& y = projectile.position[j];
    const double a = dot(y, frame.e1);
    const double b = dot(y, frame.e2);
    const double along = dot(y, frame.u);
    const double rj = projectile.radius[j];
    grid.for_each_near(a, b, [&](const ProjectedPrimary& t) {
      const double reach = t.radius + rj;
      const double da = t.a - a;
      const double db = t.b - b;
      const double offset2 = da * da + db * db;
      if (offset2 > reach * reach) return;
      // Entry root of |w + s u|^2 = reach^2: along-gap minus the half chord at this offset.
      first = std::min(first, (t.along - along) - std::sqrt(reach * reach - offset2));
    });
  }
  if (first == std::numeric_limits<double>::infinity()) return std::nullopt;
  return first;
}

}  // namespace aerobreak
