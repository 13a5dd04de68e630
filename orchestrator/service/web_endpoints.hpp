#pragma once
#include <filesystem>
#include <memory>

#include "orchestrator/service/endpoints.hpp"

namespace aerobreak {

// The dashboard's files in `web_directory` (web_assets.hpp), with a line on stderr for a folder
// without a page or a library file it lacks; null for an empty folder name (the API only).
std::shared_ptr<const WebAssets> load_web_assets(const std::filesystem::path& web_directory);

// GET / and the dashboard's files: its own files and the library files it names, with a
// Content-Security-Policy that lets the page load scripts, styles and data from this origin only
// and run no inline script; 404 when the service has no dashboard.
namespace endpoint {
void get_dashboard_file(Endpoints&, const httplib::Request&, httplib::Response&);
}  // namespace endpoint

// The paths that can name a page file: "/" and names ending in one of the served extensions, so
// that no /api/ route is shadowed, whatever the order of registration.
extern const char* const kDashboardFiles;
// The Content-Security-Policy of every page file.
extern const char* const kDashboardContentSecurityPolicy;

}  // namespace aerobreak
