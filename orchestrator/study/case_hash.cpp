#include "orchestrator/study/case_hash.hpp"

#include <stdexcept>

#include "orchestrator/study/canonical_json.hpp"
#include "orchestrator/study/sha256.hpp"
#include "orchestrator/study/study.hpp"

namespace aerobreak {
namespace {

std::string file_digest(const std::string& path, ClusterFileDigests& digests) {
  if (const auto found = digests.find(path); found != digests.end()) return found->second;
  try {
    return digests[path] = sha256_hex_of_file(path);
  } catch (const std::runtime_error& error) {
    throw std::runtime_error(std::string("cluster file: ") + error.what());
  }
}

}  // namespace

std::string case_hash(const nlohmann::ordered_json& completed_case_document, ClusterFileDigests& digests) {
  nlohmann::ordered_json physics = completed_case_document;
  // Labels are not physics: the same impact under another name is the same case.
  physics.erase("name");
  physics.erase("description");
  physics.erase("$schema");
  // A cluster file is its content: the same path holding other primaries is another case, and the
  // same primaries found under another path (another checkout, another machine) are the same.
  const auto path_pointer = nlohmann::ordered_json::json_pointer("/cluster/file/path");
  if (physics.contains(path_pointer) && physics[path_pointer].is_string()) {
    physics["cluster_file_sha256"] = file_digest(physics[path_pointer].get<std::string>(), digests);
    physics["cluster"]["file"].erase("path");
  }
  return sha256_hex("aerobreak-case-v1\n" + canonical_dump(physics));
}

std::string case_hash(const nlohmann::ordered_json& completed_case_document) {
  ClusterFileDigests digests;
  return case_hash(completed_case_document, digests);
}

}  // namespace aerobreak
