#pragma once
#include <cstdint>
#include <map>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

#include "orchestrator/store/store.hpp"

namespace aerobreak {

// The grid points of recently filtered studies: a study's grid points never change once it is
// stored, and listing them costs a pass over its cases. At most kStudies studies are kept.
class GridPointCache {
 public:
  using Points = std::vector<std::pair<std::string, nlohmann::ordered_json>>;
  std::shared_ptr<const Points> points(Store& store, std::int64_t study_id);

 private:
  static constexpr std::size_t kStudies = 32;
  std::mutex mutex_;
  std::map<std::int64_t, std::shared_ptr<const Points>> cache_;
};

}  // namespace aerobreak
