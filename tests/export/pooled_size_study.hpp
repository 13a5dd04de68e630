#pragma once
// A study in a real store file for the fit table at sizes the study did not run: eight speeds
// 0.01-0.3 d/tau x N = 32, 128, 20 replicates, with the stick / bounce / break-up counts of
// tests/fitting/reference_implementation_test.cpp (whose fits, per size and pooled in log N, R's
// glm reproduces; its comments hold the R script and output), committed through the store.
#include "tests/export/export_study.hpp"

namespace aerobreak::testing {

inline const std::vector<double> kPooledSpeeds{0.01, 0.02, 0.03, 0.05, 0.08, 0.12, 0.2, 0.3};
inline const std::vector<int> kPooledSizes{32, 128};
inline constexpr int kPooledReplicates = 20;

// Per speed: the first `stick` replicates stick, the next `bounce` bounce, the others break up.
struct OutcomeCounts {
  std::vector<int> stick, bounce;
};
inline const OutcomeCounts kCounts32{{18, 15, 12, 8, 5, 2, 1, 0}, {2, 4, 5, 6, 5, 4, 2, 1}};
inline const OutcomeCounts kCounts128{{19, 17, 14, 11, 7, 4, 2, 1}, {1, 2, 4, 5, 5, 4, 3, 1}};

// Fragments that make the class (outcome_of): stick whole; bounce: all but one monomer leave;
// break-up: a dimer and two monomers leave.
inline std::vector<Fragment> pooled_fragments(int size, std::size_t speed_index, int replicate) {
  const auto& counts = size == 32 ? kCounts32 : kCounts128;
  if (replicate < counts.stick[speed_index]) return {{size, true}};
  if (replicate < counts.stick[speed_index] + counts.bounce[speed_index]) return {{size - 1, false}, {1, true}};
  return {{size - 4, true}, {2, false}, {1, false}, {1, false}};
}

inline StudySubmission pooled_submission() {
  auto study = named_study("pooled sizes", 'p');
  study.document["axes"] = {{"impact_speed", {{"values", kPooledSpeeds}}}, {"primaries", {{"values", kPooledSizes}}}};
  for (const double speed : kPooledSpeeds)
    for (const int size : kPooledSizes)
      for (int r = 0; r < kPooledReplicates; ++r)
        study.cases.push_back(reduced_case({{"impact_speed", speed}, {"primaries", size}}, speed, 0.001, size, r));
  return study;
}

// Submits the study and commits every case's result; returns the study's id.
inline std::int64_t fill_pooled_study(Store& store) {
  return fill_study(store, pooled_submission(), [](const nlohmann::ordered_json& document) {
    const auto& generator = document.at("cluster").at("generator");
    const double speed = document.at("impact").at("speed");
    const auto s =
        static_cast<std::size_t>(std::find(kPooledSpeeds.begin(), kPooledSpeeds.end(), speed) - kPooledSpeeds.begin());
    return pooled_fragments(generator.at("primaries"), s, generator.at("seed"));
  });
}

// The same speeds, sizes and replicates on two walls (axis /wall/adhesive): the adhesive wall as
// above; the wall without adhesion with the sizes' counts swapped and every stick a bounce instead
// (nothing sticks there: its stick fits have no transition).
inline std::int64_t fill_pooled_wall_study(Store& store) {
  auto study = named_study("pooled sizes, two walls", 'q');
  study.document["axes"] = {{"impact_speed", {{"values", kPooledSpeeds}}},
                            {"/wall/adhesive", {{"values", {true, false}}}},
                            {"primaries", {{"values", kPooledSizes}}}};
  for (const double speed : kPooledSpeeds)
    for (const bool adhesive : {true, false})
      for (const int size : kPooledSizes)
        for (int r = 0; r < kPooledReplicates; ++r) {
          auto c = reduced_case({{"impact_speed", speed}, {"/wall/adhesive", adhesive}, {"primaries", size}}, speed,
                                0.001, size, r);
          c.document["wall"] = {{"adhesive", adhesive}};
          study.cases.push_back(std::move(c));
        }
  return fill_study(store, study, [](const nlohmann::ordered_json& document) {
    const auto& generator = document.at("cluster").at("generator");
    const double speed = document.at("impact").at("speed");
    const auto s =
        static_cast<std::size_t>(std::find(kPooledSpeeds.begin(), kPooledSpeeds.end(), speed) - kPooledSpeeds.begin());
    const int size = generator.at("primaries");
    const int replicate = generator.at("seed");
    if (document.at("wall").at("adhesive").get<bool>()) return pooled_fragments(size, s, replicate);
    const auto& counts = size == 32 ? kCounts128 : kCounts32;  // the other size's counts
    if (replicate < counts.stick[s] + counts.bounce[s]) return std::vector<Fragment>{{size - 1, false}, {1, true}};
    return std::vector<Fragment>{{size - 4, true}, {2, false}, {1, false}, {1, false}};
  });
}

}  // namespace aerobreak::testing
