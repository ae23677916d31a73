# Precompiled headers for the library's objects and the tool (docs/development.md, "Compile
# time"). Every unit of the library parses Eigen (model.h includes Eigen/Core and Eigen/Geometry)
# and the standard headers Eigen and the units include: 80 000 to 100 000 preprocessed lines,
# most of each unit's time where its own code is short. The tool's units add CLI11 and
# nlohmann-json. Each target's header is built once with that target's own flags and definitions
# (gcc and clang refuse a header built with others), and read by each of its units instead of the
# text. Included at the end of CMakeLists.txt, after the targets are defined.
# Every unit must still compile without them: the lint (tools/lint.sh) reads each source without.
# MASSPROPS_PCH=OFF: without them. tools/test.sh builds its three Release trees so (build/, the
# .deb's, the colcon workspace's): each tree's header has its own path on the units' command lines,
# which would stop the second and third trees from hitting the first one's objects in ccache.
option(MASSPROPS_PCH "Precompiled headers for the library and the tool" ON)
if(NOT MASSPROPS_PCH)
  return()
endif()
set(MASSPROPS_PCH_STANDARD <algorithm> <array> <cmath> <cstddef> <cstdint> <functional> <map>
    <memory> <optional> <set> <sstream> <string> <string_view> <unordered_map> <utility> <vector>)
target_precompile_headers(massprops_objects PRIVATE <Eigen/Core> <Eigen/Geometry>
                          ${MASSPROPS_PCH_STANDARD})
target_precompile_headers(massprops-cli PRIVATE <CLI/CLI.hpp> <nlohmann/json.hpp> <Eigen/Core>
                          <Eigen/Geometry> ${MASSPROPS_PCH_STANDARD} <filesystem> <fstream>
                          <iostream>)
# Generated units that are one string literal each (docs/rules.md, the page's assets) include no
# header: the precompiled one would only cost them its loading.
get_target_property(massprops_cli_sources massprops-cli SOURCES)
foreach(source ${massprops_cli_sources} "${PROJECT_BINARY_DIR}/generated/rules_md.cc")
  if(source MATCHES "^${PROJECT_BINARY_DIR}/(view_assets|generated)/")
    set_source_files_properties("${source}" PROPERTIES SKIP_PRECOMPILE_HEADERS ON)
  endif()
endforeach()
