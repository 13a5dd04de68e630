// Content hashes are the identity of cases and studies in every store made so far: a case whose
// hash changed would be run again. The expected values below were computed by aerobreak's own
// SHA-256 implementation before it was replaced by OpenSSL's (commit 1b2fffc, with a program that
// called load_study, case_hash and replicate_seed); the new code must give them bit for bit.
#include <catch2/catch.hpp>

#include <fstream>
#include <string>

#include "orchestrator/study/study.hpp"
#include "study_support.hpp"
#include "tests/support/scratch_directory.hpp"

using namespace aerobreak;
using Json = nlohmann::ordered_json;

TEST_CASE("the default study and its cases keep the hashes stored before the change to libcrypto") {
  // studies/default.study.json. Should a schema change (a new default) alter these, every stored
  // case would be run again: that is a decision to take knowingly, not a value to update. The
  // study's own hash covers its description, which the outcome classes by what leaves the wall
  // (store migration 2) rewrote. Its cases' hashes changed once, knowingly, with the v2 replicate
  // seeds (keyed by the cluster request too, docs/ORCHESTRATOR.md): a store made before runs the
  // default study's cases again.
  const Study study = load_study(testing::source_path("studies/default.study.json"));
  REQUIRE(study.cases.size() == 640);
  CHECK(study.hash == "826cc24071a9ff9bee1764529dfbbf86d84b3d282851727de8f8d7680129f97b");
  CHECK(study.cases[0].hash == "4c6d7b91dfe9f6d02d9776c24cc5a50904361ecdee0d98c5c03b4c3cb2151a89");
  CHECK(study.cases[1].hash == "64ca70e2dbb2032923a3a55e93a9cbf11de4971796b36d25917b6d0fe41182a2");
  CHECK(study.cases[319].hash == "ab695cfc4ddc901ce19de2f22e1ae51b7c3dd0f072c18627e294c37a43fe36af");
  CHECK(study.cases[639].hash == "58e9348a128da8576632421803e35c261fb09d8814e698844136bddb21b675f1");
}

TEST_CASE("a completed case document keeps its stored hash, whatever the schema's defaults become") {
  // The first case of the default study as `aerobreak study expand --json` printed it.
  const Json completed = Json::parse(R"({"name": "default | impact_speed=0.005 gamma_over_kn=0.001 primaries=32 | replicate 0",
    "units": "reduced", "cluster": {"generator": {"method": "ballistic", "geometric_standard_deviation": 1,
    "seed": 8945730363485681, "primaries": 32}, "relax": true}, "material": {"poisson_ratio": 0.3, "gamma_over_kn": 0.001},
    "model": {"normal": "jkr", "separation": "displacement", "damping": {"law": "viscoelastic", "dissipative_time": 0.05,
    "restitution": 1}, "tangential": true, "friction": 0.3, "rolling": {"enabled": true, "critical_displacement": 0.02},
    "twisting": false}, "impact": {"angle": 0, "gap": 0.01, "orientation_seed": 3881415731225364, "speed": 0.005},
    "wall": {"adhesive": true}, "classification": {"largest_fragment_share": 0.9}, "run": {"time_limit": 50000,
    "steps_per_period": 50, "settle": {"rest_speed_fraction": 0.01}}})");
  CHECK(case_hash(completed) == "479b9d26b9ca113a58da5781d2d6b0a57eef8851943808bab5175be294019368");
}

TEST_CASE("a case made from a cluster file keeps its stored hash (the file enters by its bytes)") {
  const testing::ScratchDirectory directory("stored_hashes");
  const auto file = directory.path() / "two.xyz";
  std::ofstream(file) << "2\ncomment\nX 0 0 0\nX 1 0 0\n";
  Json document = Json::parse(R"({"units": "reduced", "cluster": {"file": {"default_radius": 0.5}, "relax": true},
    "material": {"gamma_over_kn": 0.001}, "impact": {"speed": 0.01}, "run": {"time_limit": 1000}})");
  document["cluster"]["file"]["path"] = file.string();
  CHECK(case_hash(document) == "97c08a9586a86e82aafcdf0d971625fd78def7693ab4ab4f3a586a0a7061e070");
}

TEST_CASE("replicate seeds (v2) are the documented digest") {
  // Expected values from Python's hashlib, an implementation independent of aerobreak's:
  //   python3 -c "import hashlib; k='{\"method\":\"ballistic\",\"primaries\":32}'
  //   d=hashlib.sha256(f'aerobreak-seed-v2|2026|cluster|1|{k}'.encode()).digest()
  //   print(int.from_bytes(d[:8], 'big') & ((1 << 53) - 1))"   (and replicates 0 with key '', 19)
  const std::string key = R"({"method":"ballistic","primaries":32})";
  CHECK(replicate_seed(2026, "cluster", 0, "") == 547130842142006u);
  CHECK(replicate_seed(2026, "cluster", 1, key) == 7413063362078492u);
  CHECK(replicate_seed(2026, "cluster", 19, key) == 4863044663831704u);
}
