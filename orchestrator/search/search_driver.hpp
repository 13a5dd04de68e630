#pragma once
#include <cstdint>
#include <functional>
#include <map>
#include <string>

#include "orchestrator/store/store.hpp"
#include "orchestrator/study/study.hpp"

namespace aerobreak {

// Runs the adaptive searches of the store (docs/ADAPTIVE.md): every group whose last round has
// finished gets its next round decided from its results (plan_round) and stored with its cases in
// one transaction, or its end recorded. Everything it decides is a function of the stored study
// and results, so that an orchestrator restarted after a crash decides the same round again, or
// finds it stored, and reruns nothing.
class SearchDriver {
 public:
  SearchDriver(Store& store, std::function<void(const std::string&)> log);

  // Decides every round that is due; returns the cases it placed.
  std::size_t advance();

 private:
  const Study& study(std::int64_t study_id, const nlohmann::ordered_json& document);
  SearchDecision decide(const SearchGroupWork& work);

  Store& store_;
  std::function<void(const std::string&)> log_;
  std::map<std::int64_t, Study> studies_;
};

}  // namespace aerobreak
