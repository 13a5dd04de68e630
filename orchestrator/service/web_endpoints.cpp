#include "orchestrator/service/web_endpoints.hpp"

#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>

#include "orchestrator/service/http_support.hpp"
#include "orchestrator/service/web_assets.hpp"

namespace aerobreak {

const char* const kDashboardFiles = R"(/|/[A-Za-z0-9_.\-/]+\.(html|js|css|svg|png))";

const char* const kDashboardContentSecurityPolicy =
    "default-src 'none'; script-src 'self'; style-src 'self'; img-src 'self' data:; connect-src 'self'; "
    "font-src 'self'; base-uri 'none'; form-action 'none'; frame-ancestors 'none'";

namespace {

// Page files are small; a larger one is not what the web folder should hold.
constexpr std::uintmax_t kMaxAssetBytes = 8u << 20;

void send_asset(httplib::Response& response, const WebAsset& asset) {
  std::error_code error;
  const auto size = std::filesystem::file_size(asset.file, error);
  if (error || size > kMaxAssetBytes) throw RequestError{404, "the dashboard file is missing or too large"};
  std::ifstream in(asset.file, std::ios::binary);
  std::ostringstream content;
  content << in.rdbuf();
  response.set_header("Content-Security-Policy", kDashboardContentSecurityPolicy);
  response.set_header("X-Content-Type-Options", "nosniff");
  response.set_header("Referrer-Policy", "no-referrer");
  response.set_header("Cache-Control", "no-cache");
  response.set_content(content.str(), asset.content_type.c_str());
}

}  // namespace

std::shared_ptr<const WebAssets> load_web_assets(const std::filesystem::path& web_directory) {
  if (web_directory.empty()) return nullptr;
  auto assets = std::make_shared<const WebAssets>(list_web_assets(web_directory));
  if (assets->by_path.empty())
    std::cerr << "aerobreak: no dashboard: " << web_directory.string() << " holds no page (--web-dir)\n";
  for (const auto& file : assets->missing)
    std::cerr << "aerobreak: the dashboard lacks " << file << " (run scripts/setup.sh, which runs npm ci in web/)\n";
  return assets;
}

void endpoint::get_dashboard_file(Endpoints& e, const httplib::Request& request, httplib::Response& response) {
  if (!e.web_assets) throw RequestError{404, "no dashboard: this service serves the API only (--web-dir \"\")"};
  const auto found = e.web_assets->by_path.find(request.path);
  if (found == e.web_assets->by_path.end())
    throw RequestError{404, request.path == "/" ? "no dashboard in " + e.options.web_directory.string() + " (--web-dir)"
                                                : "no dashboard file " + request.path};
  send_asset(response, found->second);
}

}  // namespace aerobreak
