#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "engine/impact/json_schema.hpp"  // pointer_child

namespace aerobreak {

// The canonical form of a document, the one that content hashes are taken over: keys sorted
// (nlohmann::json), and numbers with an integral value below 2^53 written as integers, so that
// 16, 16.0 and 1.6e1 (one number to JSON and to the physics) hash the same.
nlohmann::json canonical_json(const nlohmann::ordered_json& document);
std::string canonical_dump(const nlohmann::ordered_json& document);

}  // namespace aerobreak
