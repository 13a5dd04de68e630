// The generator registry (engine/impact/cluster_generators.hpp) that cases, studies and
// `aerobreak cluster generate` share: names and aliases, requests to case documents and back, the
// rules on each generator's own fields, and each generator through a whole impact case.
#include <catch2/catch.hpp>

#include <string>
#include <vector>

#include "engine/cluster/ballistic_aggregation.hpp"
#include "engine/cluster/tunable_aggregation.hpp"
#include "engine/growth/diffusion_limited_aggregation.hpp"
#include "engine/impact/cluster_generators.hpp"
#include "engine/impact/impact_case.hpp"
#include "engine/impact/impact_result.hpp"
#include "engine/impact/impact_run.hpp"
#include "impact_support.hpp"

using namespace aerobreak;
using Json = nlohmann::ordered_json;
using Catch::Matchers::Contains;

namespace {

// A request of each generator, with its own fields set away from their defaults.
std::vector<GeneratorRequest> one_of_each() {
  GeneratorRequest ballistic;
  ballistic.primaries = 16;
  ballistic.seed = 11;
  ballistic.geometric_standard_deviation = 1.3;
  GeneratorRequest dlca;
  dlca.method = "dlca";
  dlca.primaries = 3;  // unsintered growth is slow: about a second for 3 primaries
  dlca.seed = 12;
  dlca.sintering = false;
  GeneratorRequest tunable;
  tunable.method = "tunable";
  tunable.primaries = 16;
  tunable.seed = 13;
  tunable.fractal_dimension = 2.1;
  tunable.prefactor = 1.2;
  return {ballistic, dlca, tunable};
}

bool same_request(const GeneratorRequest& a, const GeneratorRequest& b) {
  const bool own_tunable =
      a.method != "tunable" || (a.fractal_dimension == b.fractal_dimension && a.prefactor == b.prefactor);
  const bool own_dlca = a.method != "dlca" || a.sintering == b.sintering;
  return a.method == b.method && a.primaries == b.primaries && a.seed == b.seed &&
         a.geometric_standard_deviation == b.geometric_standard_deviation && own_tunable && own_dlca;
}

bool same_cluster(const Cluster& a, const Cluster& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (!(a.position[i] == b.position[i]) || a.radius[i] != b.radius[i]) return false;
  return true;
}

std::vector<std::string> fields_of(const std::vector<GeneratorViolation>& violations) {
  std::vector<std::string> fields;
  for (const auto& v : violations) fields.push_back(v.field);
  return fields;
}

}  // namespace

TEST_CASE("the generator registry round trips: names, aliases, requests to case documents and back") {
  REQUIRE(cluster_generators().size() == 3);
  for (const ClusterGenerator& g : cluster_generators()) CHECK(find_cluster_generator(g.name) == &g);
  CHECK(find_cluster_generator("bcca") == find_cluster_generator("ballistic"));
  CHECK(find_cluster_generator("dla") == nullptr);
  CHECK(cluster_generator_names() == "ballistic (alias bcca), dlca, tunable");

  for (const GeneratorRequest& request : one_of_each()) {
    INFO(request.method);
    const Json document = generator_document(request);
    std::vector<GeneratorViolation> violations;
    const GeneratorRequest back = read_generator_request(document, violations);
    CHECK(violations.empty());
    CHECK(same_request(request, back));
    CHECK(generator_document(back) == document);
    // The document holds the common fields and exactly the generator's own.
    for (const auto& [field, value] : document.items()) CHECK(generator_takes(request.method, field));
  }
  // An alias is read as its generator and written under the registered name.
  std::vector<GeneratorViolation> violations;
  const GeneratorRequest alias =
      read_generator_request({{"method", "bcca"}, {"primaries", 8}, {"seed", 1}}, violations);
  CHECK(violations.empty());
  CHECK(alias.method == "ballistic");
  CHECK(generator_document(alias)["method"] == "ballistic");
}

TEST_CASE("a generator refuses another generator's fields and requires its own") {
  std::vector<GeneratorViolation> violations;
  read_generator_request({{"method", "ballistic"}, {"primaries", 8}, {"seed", 1}, {"fractal_dimension", 1.8}},
                         violations);
  REQUIRE(fields_of(violations) == std::vector<std::string>{"fractal_dimension"});
  CHECK_THAT(violations[0].message, Contains("applies to the tunable generator only, not to ballistic"));

  violations.clear();
  read_generator_request({{"method", "tunable"}, {"primaries", 8}, {"seed", 1}, {"fractal_dimension", 1.8}},
                         violations);
  REQUIRE(fields_of(violations) == std::vector<std::string>{"prefactor"});
  CHECK_THAT(violations[0].message, Contains("required by the tunable generator"));

  violations.clear();
  read_generator_request({{"method", "dlca"}, {"primaries", 8}, {"seed", 1}, {"geometric_standard_deviation", 1.3}},
                         violations);
  CHECK(fields_of(violations) == std::vector<std::string>{"geometric_standard_deviation"});

  violations.clear();
  read_generator_request({{"method", "tunable"},
                          {"primaries", 8},
                          {"seed", 1},
                          {"fractal_dimension", 3.0},
                          {"prefactor", 1.3},
                          {"sintering", true}},
                         violations);
  CHECK(fields_of(violations) == std::vector<std::string>{"sintering", "fractal_dimension"});
}

TEST_CASE("each generator of the registry builds what its own generator function builds") {
  const std::vector<GeneratorRequest> requests = one_of_each();
  const GeneratorRequest& b = requests[0];
  CHECK(same_cluster(generate_cluster(b), ballistic_cluster_cluster_aggregation(
                                              {b.primaries, 1.0, b.geometric_standard_deviation}, b.seed)));
  DiffusionLimitedParameters dlca;
  dlca.primary_count = requests[1].primaries;
  dlca.sintering = requests[1].sintering;
  CHECK(same_cluster(generate_cluster(requests[1]), diffusion_limited_aggregation(dlca, requests[1].seed)));
  const GeneratorRequest& t = requests[2];
  TunableAggregationParameters tunable;
  tunable.primary_count = t.primaries;
  tunable.fractal_dimension = t.fractal_dimension;
  tunable.prefactor = t.prefactor;
  CHECK(same_cluster(generate_cluster(t), tunable_cluster_aggregation(tunable, t.seed)));
}

TEST_CASE("a case stores the generator's registered name and its own fields, and refuses foreign ones") {
  Json c = testing::minimal_case();
  c["cluster"]["generator"]["method"] = "bcca";
  CHECK(parse_impact_case(c).document["cluster"]["generator"] ==
        Json{{"method", "ballistic"}, {"primaries", 8}, {"seed", 3}, {"geometric_standard_deviation", 1}});
  c["cluster"]["generator"] = {{"method", "dlca"}, {"primaries", 8}, {"seed", 3}};
  CHECK(parse_impact_case(c).document["cluster"]["generator"]["sintering"] == true);

  c["cluster"]["generator"] = {{"method", "ballistic"}, {"primaries", 8}, {"seed", 3}, {"prefactor", 1.3}};
  try {
    parse_impact_case(c);
    FAIL("a ballistic generator with a prefactor was accepted");
  } catch (const CaseError& e) {
    REQUIRE(e.violations().size() == 1);
    CHECK(e.violations()[0].pointer == "/cluster/generator/prefactor");
  }
}

TEST_CASE("every generator runs through an impact case") {
  // Small clusters at a speed where the impact is short; the unsintered DLCA growth is the
  // costly one (3 primaries: about a second).
  for (const Json& generator :
       {Json{{"method", "ballistic"}, {"primaries", 8}, {"seed", 3}, {"geometric_standard_deviation", 1.2}},
        Json{{"method", "dlca"}, {"primaries", 8}, {"seed", 3}},
        Json{{"method", "dlca"}, {"primaries", 3}, {"seed", 3}, {"sintering", false}},
        Json{{"method", "tunable"}, {"primaries", 16}, {"seed", 3}, {"fractal_dimension", 1.8}, {"prefactor", 1.3}}}) {
    INFO(generator.dump());
    Json c = testing::minimal_case();
    c["cluster"]["generator"] = generator;
    c["impact"]["speed"] = 0.05;
    c["run"]["time_limit"] = 300.0;
    const ImpactCase impact = parse_impact_case(c);
    const ImpactResult result = run_impact(impact);
    const Json document = to_json(result);
    CHECK(validate_result(document).empty());
    CHECK(result.primaries == generator["primaries"].get<std::size_t>());
    CHECK(document["case"]["cluster"]["generator"]["method"] == generator["method"]);
    CHECK(document["setup"]["cluster_source"] == generator["method"]);
    CHECK(result.relaxation.performed);
  }
}
