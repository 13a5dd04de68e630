#include <string>

#include "orchestrator/study/sha256.hpp"
#include "orchestrator/study/study.hpp"

namespace aerobreak {

std::uint64_t replicate_seed(std::uint64_t study_seed, const std::string& stream, int replicate,
                             const std::string& sample_key) {
  // A hash rather than a generator advanced r times: seed r does not depend on how many replicates
  // the study has, so adding replicates later keeps the ones already run.
  const auto digest = sha256("aerobreak-seed-v2|" + std::to_string(study_seed) + "|" + stream + "|" +
                             std::to_string(replicate) + "|" + sample_key);
  std::uint64_t seed = 0;
  for (int k = 0; k < 8; ++k) seed = (seed << 8) | digest[k];
  constexpr std::uint64_t kJsonSafe = (std::uint64_t{1} << 53) - 1;
  return seed & kJsonSafe;
}

}  // namespace aerobreak
