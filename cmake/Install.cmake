# `cmake --install build --prefix P`: what a site installs (README, "Installing").
#   P/bin/aerobreak                  the program (workers run it too)
#   P/share/aerobreak/web/           the dashboard, with the npm files web/vendor.json lists
#   P/share/aerobreak/schemas/       the JSON Schemas and openapi.json (also compiled in)
#   P/share/aerobreak/studies/       the ready-to-run studies and example cases
#   P/share/doc/aerobreak/           README.md and docs/
# The installed aerobreak finds its dashboard from where it runs (../share/aerobreak/web beside its
# bin/), so that the prefix may be moved as a whole.
install(TARGETS aerobreak RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})

set(aerobreak_share ${CMAKE_INSTALL_DATADIR}/aerobreak)
# The files the service serves from web/ (orchestrator/service/web_assets.cpp), node_modules aside.
install(DIRECTORY web/ DESTINATION ${aerobreak_share}/web FILES_MATCHING PATTERN "*.html" PATTERN "*.js"
  PATTERN "*.css" PATTERN "*.svg" PATTERN "*.png" PATTERN "vendor.json" PATTERN "node_modules" EXCLUDE)
# The npm files the dashboard serves, each at the path vendor.json names (under node_modules/).
file(READ ${PROJECT_SOURCE_DIR}/web/vendor.json vendor_list)
string(JSON vendor_count LENGTH "${vendor_list}")
math(EXPR vendor_last "${vendor_count} - 1")
foreach(index RANGE ${vendor_last})
  string(JSON url MEMBER "${vendor_list}" ${index})
  string(JSON file GET "${vendor_list}" "${url}")
  get_filename_component(folder ${file} DIRECTORY)
  install(FILES web/${file} DESTINATION ${aerobreak_share}/web/${folder})
endforeach()
set_property(DIRECTORY APPEND PROPERTY CMAKE_CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/web/vendor.json)

install(DIRECTORY schemas/ DESTINATION ${aerobreak_share}/schemas FILES_MATCHING PATTERN "*.json")
install(DIRECTORY studies/ DESTINATION ${aerobreak_share}/studies FILES_MATCHING PATTERN "*.json")
install(FILES README.md DESTINATION ${CMAKE_INSTALL_DOCDIR})
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR}/docs FILES_MATCHING PATTERN "*.md" PATTERN "*.png"
  PATTERN "*.svg")
