// Study::cases: every combination of one value per axis (first axis slowest, replicates fastest),
// ranges with exact end points, replicate seeds derived from the study seed, the replicate and what
// builds the cluster.
#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>

#include "engine/impact/cluster_generators.hpp"
#include "orchestrator/study/sha256.hpp"
#include "study_support.hpp"

using namespace aerobreak;
using aerobreak::testing::minimal_study;
using Json = nlohmann::ordered_json;

namespace {

Json ptr(const Json& document, const std::string& pointer) { return document.at(Json::json_pointer(pointer)); }

// The replicate seed computed here from its definition, independently of replicate_seed().
std::uint64_t expected_seed(std::uint64_t study_seed, const std::string& stream, int replicate,
                            const std::string& key) {
  const std::string hex = sha256_hex("aerobreak-seed-v2|" + std::to_string(study_seed) + "|" + stream + "|" +
                                     std::to_string(replicate) + "|" + key);
  return std::stoull(hex.substr(0, 16), nullptr, 16) & ((std::uint64_t{1} << 53) - 1);
}

// The sample key of a ballistic cluster of `primaries` (docs/ORCHESTRATOR.md): its completed
// generator without the seed, keys sorted.
std::string ballistic_key(int primaries) {
  return R"(generator {"geometric_standard_deviation":1,"method":"ballistic","primaries":)" +
         std::to_string(primaries) + "}";
}

Json grid_study() {
  Json s = minimal_study();
  s["axes"] = Json::parse(R"({
    "impact_speed": {"values": [0.01, 0.02]},
    "gamma_over_kn": {"log": {"from": 1e-4, "to": 1e-2, "count": 3}},
    "primaries": {"linear": {"from": 8, "to": 16, "count": 2}}
  })");
  s["replicates"] = {{"count", 2}, {"seed", 2026}};
  return s;
}

}  // namespace

TEST_CASE("cases run through the axes in key order, the first slowest, replicates fastest") {
  const Study study = parse_study(grid_study());
  REQUIRE(study.case_count() == 24);
  const auto cases = study.cases;
  REQUIRE(cases.size() == 24);

  std::size_t k = 0;
  for (double speed : {0.01, 0.02})
    for (double gamma : {1e-4, 1e-3, 1e-2})
      for (int primaries : {8, 16})
        for (int replicate : {0, 1}) {
          INFO("case " << k);
          const StudyCase& c = cases[k++];
          CHECK(c.grid_point == Json{{"impact_speed", speed}, {"gamma_over_kn", gamma}, {"primaries", primaries}});
          CHECK(c.grid_key == c.grid_point.dump());
          CHECK(c.replicate == replicate);
          CHECK(ptr(c.document, "/impact/speed") == speed);
          CHECK(ptr(c.document, "/material/gamma_over_kn") == gamma);
          CHECK(ptr(c.document, "/cluster/generator/primaries") == primaries);
          CHECK(ptr(c.document, "/cluster/generator/primaries").is_number_integer());
        }

  std::set<std::string> hashes, keys;
  for (const auto& c : cases) {
    hashes.insert(c.hash);
    keys.insert(c.grid_key);
  }
  CHECK(hashes.size() == 24);
  CHECK(keys.size() == 12);
}

TEST_CASE("case documents are complete, named after the study, grid point and replicate") {
  Json s = grid_study();
  s["description"] = "not copied";
  s["base"]["description"] = "not copied either";
  const auto cases = parse_study(s).cases;
  const Json& d = cases[5].document;
  CHECK(d["name"] == "test study | impact_speed=0.01 gamma_over_kn=0.001 primaries=8 | replicate 1");
  CHECK(d.begin().key() == "name");
  CHECK_FALSE(d.contains("description"));
  // Defaults the base left out are filled in.
  CHECK(d["model"]["friction"] == 0.5);
  CHECK(d["impact"]["gap"] == 0.01);
  CHECK(d["units"] == "reduced");
}

TEST_CASE("linear and log ranges include both end points exactly") {
  Json s = minimal_study();
  s["axes"]["impact_speed"] = {{"linear", {{"from", 0.1}, {"to", 0.7}, {"count", 7}}}};
  s["axes"]["gamma_over_kn"] = {{"log", {{"from", 0.003}, {"to", 0.07}, {"count", 5}}}};
  const Study study = parse_study(s);
  const auto& speeds = study.axes[0].values;
  REQUIRE(speeds.size() == 7);
  CHECK(speeds.front().get<double>() == 0.1);
  CHECK(speeds.back().get<double>() == 0.7);  // 0.1 + 6 x 0.1 would be 0.7000000000000001
  for (std::size_t k = 1; k < speeds.size(); ++k)
    CHECK(speeds[k].get<double>() - speeds[k - 1].get<double>() == Approx(0.1).epsilon(1e-12));

  const auto& gammas = study.axes[1].values;
  REQUIRE(gammas.size() == 5);
  CHECK(gammas.front().get<double>() == 0.003);
  CHECK(gammas.back().get<double>() == 0.07);
  const double ratio = std::pow(0.07 / 0.003, 0.25);
  for (std::size_t k = 1; k < gammas.size(); ++k)
    CHECK(gammas[k].get<double>() / gammas[k - 1].get<double>() == Approx(ratio).epsilon(1e-12));

  s["axes"]["gamma_over_kn"] = {{"log", {{"from", 1e-4}, {"to", 1e-2}, {"count", 3}}}};
  CHECK(Json(parse_study(s).axes[1].values) == Json{1e-4, 1e-3, 1e-2});
}

TEST_CASE("values inside a range are the decimal numbers a user would type") {
  // 0.1 + 0.9 x 2/9 is 0.30000000000000004 and 10^(log10(0.003) + 1) is 0.030000000000000013: both
  // are rounded to 15 significant digits.
  Json s = minimal_study();
  s["axes"]["impact_speed"] = {{"linear", {{"from", 0.1}, {"to", 1.0}, {"count", 10}}}};
  s["axes"]["gamma_over_kn"] = {{"log", {{"from", 0.003}, {"to", 0.3}, {"count", 5}}}};
  const Study study = parse_study(s);
  CHECK(Json(study.axes[0].values) == Json{0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0});
  CHECK(study.axes[1].values[2].get<double>() == 0.03);
  CHECK(study.axes[1].values[1].dump() == "0.00948683298050514");
}

TEST_CASE("replicate r gets seeds derived from the study seed, r and the cluster, the same along speed and gamma") {
  const auto cases = parse_study(grid_study()).cases;
  std::set<std::uint64_t> cluster_seeds, orientation_seeds;
  for (const auto& c : cases) {
    const auto cluster = ptr(c.document, "/cluster/generator/seed").get<std::uint64_t>();
    const auto orientation = ptr(c.document, "/impact/orientation_seed").get<std::uint64_t>();
    const std::string key = ballistic_key(ptr(c.document, "/cluster/generator/primaries").get<int>());
    CHECK(cluster == expected_seed(2026, "cluster", c.replicate, key));
    CHECK(orientation == expected_seed(2026, "orientation", c.replicate, key));
    CHECK(cluster == replicate_seed(2026, "cluster", c.replicate, key));
    CHECK(cluster < (std::uint64_t{1} << 53));
    cluster_seeds.insert(cluster);
    orientation_seeds.insert(orientation);
  }
  // Two replicates of two sizes: four seeds per stream over all 24 cases, each shared by the six
  // (speed, gamma/k_n) grid points of its size.
  CHECK(cluster_seeds.size() == 4);
  CHECK(orientation_seeds.size() == 4);
  CHECK(replicate_seed(2026, "cluster", 0, "k") != replicate_seed(2027, "cluster", 0, "k"));
  CHECK(replicate_seed(2026, "cluster", 0, "k") != replicate_seed(2026, "orientation", 0, "k"));
  CHECK(replicate_seed(2026, "cluster", 0, "k") != replicate_seed(2026, "cluster", 0, "l"));
}

TEST_CASE("the seeds of replicate r do not depend on how many replicates the study has") {
  Json s = grid_study();
  const auto two = parse_study(s).cases;
  s["replicates"]["count"] = 5;
  const auto five = parse_study(s).cases;
  CHECK(two[1].hash == five[1].hash);
  CHECK(two[1].document["cluster"] == five[1].document["cluster"]);
}

TEST_CASE("an axis setting a seed wins over the derived one") {
  Json s = grid_study();
  s["axes"]["/impact/orientation_seed"] = {{"values", {5, 6}}};
  const auto cases = parse_study(s).cases;
  REQUIRE(cases.size() == 48);
  CHECK(ptr(cases[0].document, "/impact/orientation_seed") == 5);
  CHECK(ptr(cases[1].document, "/impact/orientation_seed") == 5);  // replicate 1, same swept seed
  CHECK(ptr(cases[2].document, "/impact/orientation_seed") == 6);
  CHECK(ptr(cases[1].document, "/cluster/generator/seed") == replicate_seed(2026, "cluster", 1, ballistic_key(8)));
}

TEST_CASE("a cluster read from a file gets no generator seed, only an orientation seed") {
  const aerobreak::testing::ScratchDirectory scratch("file_seed");
  Json s = grid_study();
  s["axes"].erase("primaries");
  s["base"]["cluster"] = {{"file", {{"path", scratch.write("rod.xyz", aerobreak::testing::kRodXyz).string()}}}};
  const auto cases = parse_study(s).cases;
  REQUIRE(cases.size() == 12);
  CHECK_FALSE(cases[0].document["cluster"].contains("generator"));
  CHECK(ptr(cases[1].document, "/impact/orientation_seed") ==
        replicate_seed(2026, "orientation", 1, "file " + cases[1].document["cluster"]["file"]["path"].dump()));
}

namespace {

Json generator_study() {
  Json s = minimal_study();
  s["base"]["cluster"]["generator"] = {{"fractal_dimension", 1.8}, {"prefactor", 1.3}, {"sintering", false}};
  s["base"]["material"]["gamma_over_kn"] = 0.01;
  s["axes"] = Json::parse(R"({
    "generator": {"values": ["ballistic", "dlca", "tunable"]},
    "impact_speed": {"values": [0.01, 0.02]},
    "primaries": {"values": [8]}
  })");
  s["replicates"] = {{"count", 2}, {"seed", 2026}};
  return s;
}

Cluster cluster_of(const StudyCase& c) {
  std::vector<GeneratorViolation> violations;
  const GeneratorRequest request = read_generator_request(c.document["cluster"]["generator"], violations);
  REQUIRE(violations.empty());
  return generate_cluster(request);
}

// Whether `small`, moved as a whole, lies on primaries of `large`: a sub-cluster of it.
bool sub_cluster(const Cluster& small, const Cluster& large) {
  for (const Vec3& anchor : large.position) {
    const Vec3 shift = anchor - small.position[0];
    bool all = true;
    for (std::size_t k = 0; k < small.size() && all; ++k)
      all = std::any_of(large.position.begin(), large.position.end(),
                        [&](const Vec3& x) { return norm(small.position[k] + shift - x) < 1e-9; });
    if (all) return true;
  }
  return false;
}

}  // namespace

TEST_CASE("a generator axis gives each case its generator's fields from the base and its own cluster") {
  const auto cases = parse_study(generator_study()).cases;
  REQUIRE(cases.size() == 12);
  for (const auto& c : cases) {
    const Json& generator = c.document["cluster"]["generator"];
    const std::string method = c.grid_point["generator"];
    INFO(method);
    CHECK(generator["method"] == method);
    CHECK(generator.contains("fractal_dimension") == (method == "tunable"));
    CHECK(generator.contains("prefactor") == (method == "tunable"));
    CHECK(generator.contains("sintering") == (method == "dlca"));
  }
  // Replicate 0 at speed 0.01: one seed per generator (each builds another cluster); the same
  // seeds at speed 0.02.
  std::set<std::uint64_t> seeds;
  for (std::size_t k : {0, 4, 8}) seeds.insert(ptr(cases[k].document, "/cluster/generator/seed").get<std::uint64_t>());
  CHECK(seeds.size() == 3);
  for (std::size_t k : {0, 4, 8}) {
    CHECK(cases[k].document["cluster"] == cases[k + 2].document["cluster"]);
    CHECK(cases[k].document["impact"]["orientation_seed"] == cases[k + 2].document["impact"]["orientation_seed"]);
  }
}

TEST_CASE("fractal dimension and prefactor axes sweep the tunable generator, another generator refuses them") {
  Json s = minimal_study();
  s["base"]["cluster"]["generator"] = {{"method", "tunable"}};
  s["base"]["impact"]["speed"] = 0.01;
  s["base"]["material"]["gamma_over_kn"] = 0.001;
  s["axes"] = Json::parse(R"({
    "fractal_dimension": {"values": [1.6, 1.8, 2.0]},
    "prefactor": {"values": [1.2, 1.4]},
    "primaries": {"values": [16]}
  })");
  const auto cases = parse_study(s).cases;
  REQUIRE(cases.size() == 6);
  std::set<std::uint64_t> seeds;
  for (const auto& c : cases) {
    CHECK(ptr(c.document, "/cluster/generator/fractal_dimension") == c.grid_point["fractal_dimension"]);
    CHECK(ptr(c.document, "/cluster/generator/prefactor") == c.grid_point["prefactor"]);
    seeds.insert(ptr(c.document, "/cluster/generator/seed").get<std::uint64_t>());
  }
  CHECK(seeds.size() == 6);

  s["base"]["cluster"]["generator"].erase("method");
  s["axes"]["generator"] = {{"values", {"ballistic", "tunable"}}};
  const auto violations = testing::violations_of(s);
  CHECK_THAT(testing::message_at(violations, "/axes/fractal_dimension"),
             Catch::Matchers::Contains("applies to the tunable generator only, not to ballistic"));
  // An alias of the same generator is the same physics.
  s = generator_study();
  s["axes"]["generator"] = {{"values", {"ballistic", "bcca"}}};
  CHECK_THAT(testing::message_at(testing::violations_of(s), "/axes"), Catch::Matchers::Contains("the same physics"));
}

TEST_CASE("the N = 32 cluster of a replicate is no sub-cluster of its N = 128 one, two speeds share the cluster") {
  Json s = minimal_study();
  s["axes"] = Json::parse(R"({"primaries": {"values": [32, 128]}, "impact_speed": {"values": [0.01, 0.02]}})");
  s["base"]["material"]["gamma_over_kn"] = 0.01;
  s["replicates"] = {{"count", 2}, {"seed", 2026}};
  const auto cases = parse_study(s).cases;
  REQUIRE(cases.size() == 8);  // N slowest, then speed, replicates fastest
  for (int r : {0, 1}) {
    INFO("replicate " << r);
    const StudyCase& small = cases[r];
    const StudyCase& small_faster = cases[2 + r];
    const StudyCase& large = cases[4 + r];
    CHECK(small_faster.grid_point["impact_speed"] == 0.02);
    CHECK(small.document["cluster"] == small_faster.document["cluster"]);
    CHECK(small.document["impact"]["orientation_seed"] == small_faster.document["impact"]["orientation_seed"]);
    CHECK(small.document["impact"]["orientation_seed"] != large.document["impact"]["orientation_seed"]);
    const Cluster small_cluster = cluster_of(small);
    CHECK_FALSE(sub_cluster(small_cluster, cluster_of(large)));
    // What a seed shared by both sizes gave (the depth-first ballistic generator builds the first
    // 32 primaries of a 128 exactly as the 32 alone): the check above can fail.
    GeneratorRequest shared;
    shared.primaries = 128;
    shared.seed = ptr(small.document, "/cluster/generator/seed").get<std::uint64_t>();
    CHECK(sub_cluster(small_cluster, generate_cluster(shared)));
  }
}
