#pragma once
#include <httplib.h>

#include "orchestrator/service/service.hpp"

namespace aerobreak {

// The dashboard at `/` (web_assets.hpp): its own files and the library files it names, with a
// Content-Security-Policy that lets the page load scripts, styles and data from this origin only
// and run no inline script. Nothing is registered when options.web_directory is empty.
void register_web_endpoints(httplib::Server& server, const ServiceOptions& options);

// The Content-Security-Policy of every page file.
extern const char* const kDashboardContentSecurityPolicy;

}  // namespace aerobreak
