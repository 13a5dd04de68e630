#include "orchestrator/service/study_templates.hpp"

namespace aerobreak {

const nlohmann::ordered_json& study_templates_json() {
  static const nlohmann::ordered_json templates = [] {
    auto document = nlohmann::ordered_json::parse(default_study_text());
    document.erase("$schema");
    nlohmann::ordered_json item{{"name", "default"}, {"file", "studies/default.study.json"}, {"document", document}};
    return nlohmann::ordered_json{{"items", nlohmann::ordered_json::array({item})}};
  }();
  return templates;
}

}  // namespace aerobreak
