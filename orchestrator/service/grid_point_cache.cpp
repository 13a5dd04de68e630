#include "orchestrator/service/grid_point_cache.hpp"

namespace aerobreak {

std::shared_ptr<const GridPointCache::Points> GridPointCache::points(Store& store, std::int64_t study_id) {
  {
    std::lock_guard lock(mutex_);
    if (const auto found = cache_.find(study_id); found != cache_.end()) return found->second;
  }
  auto points = std::make_shared<const Points>(store.grid_points(study_id));
  std::lock_guard lock(mutex_);
  if (cache_.size() >= kStudies) cache_.clear();
  cache_[study_id] = points;
  return points;
}

}  // namespace aerobreak
