# dem::version: the generated header dem/version.h (DEM_VERSION), so every
# program reports the one version project(VERSION) sets.
configure_file(${PROJECT_SOURCE_DIR}/cmake/version.h.in ${PROJECT_BINARY_DIR}/generated/version/dem/version.h @ONLY)
add_library(dem_version INTERFACE)
target_include_directories(dem_version INTERFACE
  $<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/generated/version>
  $<INSTALL_INTERFACE:include>)
add_library(dem::version ALIAS dem_version)
