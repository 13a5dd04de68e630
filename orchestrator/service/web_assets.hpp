#pragma once
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace aerobreak {

// One file of the dashboard: where it lies and its media type.
struct WebAsset {
  std::filesystem::path file;
  std::string content_type;
};

// The dashboard's URL paths and the files behind them, listed once when the service starts, so that
// no request names a file itself:
//  - every .html, .js, .css, .svg and .png file under the web folder, node_modules/ and hidden
//    entries left out ("/" is index.html);
//  - the library files that the folder's vendor.json maps, {"/vendor/NAME": "node_modules/PATH"}:
//    only those, never the rest of node_modules/.
struct WebAssets {
  std::map<std::string, WebAsset> by_path;
  std::vector<std::string> missing;  // vendor.json entries whose file is absent (npm ci not run?)
};

// Throws std::runtime_error for a vendor.json that is not such a map or names a path outside
// node_modules/.
WebAssets list_web_assets(const std::filesystem::path& web_directory);

}  // namespace aerobreak
