#include "orchestrator/service/web_assets.hpp"

#include <array>
#include <fstream>
#include <stdexcept>
#include <utility>

#include <nlohmann/json.hpp>

namespace aerobreak {
namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 5> kContentTypes{{
    {".html", "text/html; charset=utf-8"},
    {".js", "text/javascript; charset=utf-8"},
    {".css", "text/css; charset=utf-8"},
    {".svg", "image/svg+xml"},
    {".png", "image/png"},
}};

std::string content_type(const std::filesystem::path& file) {
  for (const auto& [extension, type] : kContentTypes)
    if (file.extension() == extension) return std::string(type);
  return {};
}

bool hidden(const std::filesystem::path& name) { return name.string().rfind('.', 0) == 0; }

void add_page_files(const std::filesystem::path& web_directory, WebAssets& assets) {
  for (auto entry = std::filesystem::recursive_directory_iterator(web_directory);
       entry != std::filesystem::recursive_directory_iterator(); ++entry) {
    const auto name = entry->path().filename();
    if (entry->is_directory() && (name == "node_modules" || hidden(name))) {
      entry.disable_recursion_pending();
      continue;
    }
    const auto type = content_type(entry->path());
    if (!entry->is_regular_file() || entry->is_symlink() || hidden(name) || type.empty()) continue;
    // Appended rather than "/" + path: GCC 12 warns (-Wrestrict, a false positive) about inserting
    // in front of a temporary string.
    std::string url = "/";
    url += entry->path().lexically_relative(web_directory).generic_string();
    assets.by_path[url] = {entry->path(), type};
  }
  if (const auto index = assets.by_path.find("/index.html"); index != assets.by_path.end())
    assets.by_path["/"] = index->second;
}

bool safe_vendor_entry(const std::string& url, const std::filesystem::path& file) {
  if (url.rfind("/vendor/", 0) != 0 || url.find("..") != std::string::npos) return false;
  if (file.is_absolute() || file.empty() || *file.begin() != "node_modules") return false;
  for (const auto& part : file)
    if (part == "..") return false;
  return !content_type(file).empty();
}

void add_vendor_files(const std::filesystem::path& web_directory, WebAssets& assets) {
  const auto list_file = web_directory / "vendor.json";
  std::ifstream in(list_file);
  if (!in) return;
  const auto list = nlohmann::json::parse(in, nullptr, false);
  if (!list.is_object()) throw std::runtime_error(list_file.string() + " is not a JSON object");
  for (const auto& [url, target] : list.items()) {
    const std::filesystem::path relative = target.is_string() ? target.get<std::string>() : std::string();
    if (!safe_vendor_entry(url, relative))
      throw std::runtime_error(list_file.string() + ": '" + url +
                               "' must map /vendor/NAME to a file under node_modules/");
    const auto file = web_directory / relative;
    if (!std::filesystem::is_regular_file(file)) assets.missing.push_back(file.string());
    assets.by_path[url] = {file, content_type(file)};
  }
}

}  // namespace

WebAssets list_web_assets(const std::filesystem::path& web_directory) {
  WebAssets assets;
  if (!std::filesystem::is_directory(web_directory)) return assets;
  add_page_files(web_directory, assets);
  add_vendor_files(web_directory, assets);
  return assets;
}

}  // namespace aerobreak
