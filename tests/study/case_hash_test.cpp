// Content hashes: a case is identified by its physics (completed with the defaults, labels left
// out, a cluster file by its bytes), a study by what was submitted.
#include <catch2/catch.hpp>

#include <set>
#include <string>

#include "study_support.hpp"

using namespace aerobreak;
using aerobreak::testing::minimal_study;
using Json = nlohmann::ordered_json;

namespace {

// The same document with the keys of every object in reverse order.
Json reversed_keys(const Json& document) {
  if (!document.is_object()) return document;
  Json out = Json::object();
  std::vector<std::string> keys;
  for (const auto& [key, unused] : document.items()) keys.push_back(key);
  for (auto k = keys.rbegin(); k != keys.rend(); ++k) out[*k] = reversed_keys(document[*k]);
  return out;
}

std::set<std::string> case_hashes(const Json& study) {
  std::set<std::string> out;
  for (const auto& c : parse_study(study).cases) out.insert(c.hash);
  return out;
}

Json first_case(const Json& study) { return parse_study(study).cases.front().document; }

}  // namespace

TEST_CASE("case hashes do not depend on key order or labels") {
  Json s = minimal_study();
  s["replicates"] = {{"count", 2}, {"seed", 9}};
  Json relabelled = reversed_keys(s);
  relabelled["name"] = "another name";
  relabelled["description"] = "another description";
  relabelled["$schema"] = "../schemas/study.schema.json";
  relabelled["base"]["name"] = "a base name";
  relabelled["base"]["description"] = "a base description";
  // Reversed axes also reverse the order of the cases and of their names: compare the sets.
  const auto hashes = case_hashes(s);
  CHECK(hashes.size() == 4);
  CHECK(case_hashes(relabelled) == hashes);

  const Json c = first_case(s);
  Json other = reversed_keys(c);
  other["name"] = "renamed";
  other["description"] = "described";
  other["$schema"] = "case.schema.json";
  CHECK(case_hash(other) == case_hash(c));
}

TEST_CASE("any change of physics changes the case hash") {
  const Json c = first_case(minimal_study());
  const std::string reference = case_hash(c);
  auto changed = [&](const std::string& pointer, const Json& value) {
    Json other = c;
    other[Json::json_pointer(pointer)] = value;
    return case_hash(other);
  };
  CHECK(changed("/impact/speed", 0.0100000001) != reference);
  CHECK(changed("/cluster/generator/seed", c["cluster"]["generator"]["seed"].get<std::uint64_t>() + 1) != reference);
  CHECK(changed("/impact/orientation_seed", 1) != reference);
  CHECK(changed("/model/friction", 0.6) != reference);
  CHECK(changed("/run/time_limit", 5001) != reference);
  CHECK(changed("/wall/adhesive", false) != reference);

  Json seeded = minimal_study();
  seeded["replicates"] = {{"seed", 1}};
  CHECK(case_hashes(seeded) != case_hashes(minimal_study()));
}

TEST_CASE("a default made explicit gives the same hash: cases are hashed completed") {
  Json explicit_defaults = minimal_study();
  explicit_defaults["base"]["units"] = "reduced";
  explicit_defaults["base"]["model"] = {{"friction", 0.5}, {"damping", {{"law", "none"}}}};
  explicit_defaults["base"]["wall"] = {{"adhesive", true}};
  explicit_defaults["base"]["cluster"]["relax"] = true;
  explicit_defaults["replicates"] = {{"count", 1}, {"seed", 0}};
  CHECK(case_hashes(explicit_defaults) == case_hashes(minimal_study()));

  Json not_default = explicit_defaults;
  not_default["base"]["model"]["friction"] = 0.25;
  CHECK(case_hashes(not_default) != case_hashes(minimal_study()));
}

TEST_CASE("a number hashes the same however it is written") {
  Json c = first_case(minimal_study());
  const std::string reference = case_hash(c);
  c["cluster"]["generator"]["primaries"] = 8.0;
  c["run"]["time_limit"] = 5e3;
  CHECK(case_hash(c) == reference);
}

TEST_CASE("a cluster file enters the case hash by its content, not its path") {
  const aerobreak::testing::ScratchDirectory scratch("hash_file");
  const auto rod = scratch.write("rod.xyz", aerobreak::testing::kRodXyz);
  const auto copy = scratch.write("copy.xyz", aerobreak::testing::kRodXyz);
  const auto bent = scratch.write("bent.xyz", "4\nbent\nC 0 0 0\nC 1 0 0\nC 2 0 0\nC 2 1 0\n");
  Json c = first_case(minimal_study());
  c["cluster"] = {{"file", {{"path", rod.string()}, {"default_radius", 0.5}}}, {"relax", true}};
  const std::string reference = case_hash(c);

  Json elsewhere = c;
  elsewhere["cluster"]["file"]["path"] = copy.string();
  CHECK(case_hash(elsewhere) == reference);

  Json other_cluster = c;
  other_cluster["cluster"]["file"]["path"] = bent.string();
  CHECK(case_hash(other_cluster) != reference);

  scratch.write("rod.xyz", "4\nrod, now spaced wider\nC 0 0 0\nC 1.01 0 0\nC 2.02 0 0\nC 3.03 0 0\n");
  CHECK(case_hash(c) != reference);

  Json missing = c;
  missing["cluster"]["file"]["path"] = (scratch.path() / "absent.xyz").string();
  CHECK_THROWS_AS(case_hash(missing), std::runtime_error);
}

TEST_CASE("the study hash covers what was submitted, completed, but not the schema reference") {
  const Json s = minimal_study();
  const std::string reference = parse_study(s).hash;
  CHECK(reference.size() == 64);

  Json same = reversed_keys(s);
  same["$schema"] = "../schemas/study.schema.json";
  same["execution"] = {{"max_attempts", 3}};
  CHECK(parse_study(same).hash == reference);

  Json renamed = s;
  renamed["name"] = "another study";
  CHECK(parse_study(renamed).hash != reference);
  Json retimed = s;
  retimed["execution"] = {{"case_wall_time", 60}};
  CHECK(parse_study(retimed).hash != reference);
  Json more = s;
  more["replicates"] = {{"count", 2}};
  CHECK(parse_study(more).hash != reference);
}
