# Writes build-time version information (project version + git commit) into a generated source.
# The commit is re-read at every build, so `aerobreak --version` never reports a stale commit.
set(AEROBREAK_VERSION_CPP "${CMAKE_BINARY_DIR}/generated/version.cpp")
add_custom_target(aerobreak_version_info
  COMMAND ${CMAKE_COMMAND}
          -DSOURCE_DIR=${CMAKE_SOURCE_DIR}
          -DOUTPUT=${AEROBREAK_VERSION_CPP}
          -DVERSION=${PROJECT_VERSION}
          -P ${CMAKE_SOURCE_DIR}/cmake/WriteVersion.cmake
  BYPRODUCTS ${AEROBREAK_VERSION_CPP}
  COMMENT "Reading git commit for version info")
