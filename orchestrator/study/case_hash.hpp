#pragma once
#include <map>
#include <nlohmann/json.hpp>
#include <string>

namespace aerobreak {

// sha256 of each cluster file read so far, by path: a study whose cases share a cluster file
// reads it once.
using ClusterFileDigests = std::map<std::string, std::string>;

// case_hash (study.hpp) with the cluster file digests looked up in, and added to, `digests`.
std::string case_hash(const nlohmann::ordered_json& completed_case_document, ClusterFileDigests& digests);

}  // namespace aerobreak
