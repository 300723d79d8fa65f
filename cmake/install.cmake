# What `cmake --install` puts where (GNU layout under the prefix), the
# package configuration other CMake projects find with find_package(dem),
# and the Debian packages CPack builds from the same rules (docs/INSTALL.md):
# the component `runtime` is the package dem (programs, Python client,
# data, documents), `development` the package dem-dev (libraries,
# headers, CMake configuration):
#   bin/                      dem_run, dem_validate, dem_vtk, dem_server, demctl
#   lib/, include/dem/        the libraries (dem::engine, dem::analysis, dem::io, dem::client, ...) and their headers
#   lib/cmake/dem/            demConfig.cmake, demTargets.cmake
#   lib/python3/dist-packages/dem   the Python client with its extension (Debian's path)
#   share/dem/                cases/, config/, paraview/, ros2/dem_interfaces/
#   share/doc/dem/            README.md, LICENSE, docs/
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

# --- programs -----------------------------------------------------------
foreach(program dem_run dem_validate dem_vtk dem_server demctl)
  if(TARGET ${program})
    install(TARGETS ${program} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} COMPONENT runtime)
  endif()
endforeach()

# --- libraries for find_package(dem) -----------------------------------
# target -> (export name, its public include directory in the build). The
# libraries' own CMakeLists name their include directories for the build
# only; here each gets its installed form too, so the export can carry it.
set(exported_libraries
  dem_warnings warnings ""
  dem_version version ""
  dem_engine engine ${PROJECT_SOURCE_DIR}/engine/include
  dem_analysis analysis ${PROJECT_SOURCE_DIR}/analysis/include
  dem_idl_proto idl_proto ${PROJECT_BINARY_DIR}/idl
  dem_io io ${PROJECT_SOURCE_DIR}/io/include)
if(DEM_USES_DDS)
  list(APPEND exported_libraries
    dem_dds dds ${PROJECT_SOURCE_DIR}/dds/include
    dem_idl_dds idl_dds ${PROJECT_BINARY_DIR}/idl
    dem_protocol protocol ${PROJECT_SOURCE_DIR}/protocol/include)
  if(TARGET dem_client)
    list(APPEND exported_libraries dem_client client ${PROJECT_SOURCE_DIR}/clients/cpp/include)
  endif()
endif()
set(export_targets)
while(exported_libraries)
  list(POP_FRONT exported_libraries target export_name include_dir)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  if(include_dir)
    set_property(TARGET ${target} PROPERTY INTERFACE_INCLUDE_DIRECTORIES
      "$<BUILD_INTERFACE:${include_dir}>" "$<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>")
  endif()
  list(APPEND export_targets ${target})
  # The headers are C++20: a program built against them gets the standard
  # from the targets it links, not from settings of its own.
  target_compile_features(${target} INTERFACE cxx_std_20)
endwhile()
if(DEM_USES_DDS)
  # The messages' C++ types are generated from the IDL into the build tree.
  set_property(TARGET dem_protocol APPEND PROPERTY INTERFACE_INCLUDE_DIRECTORIES
    "$<BUILD_INTERFACE:${PROJECT_BINARY_DIR}/protocol/generated/include>")
endif()
# The build's global settings that change what a header means: Eigen's
# vectorisation changes the layout of its fixed-size vectors (and so of
# every definition struct), and the instruction set what inline code is.
# A program built against the installed libraries must use the same.
target_compile_definitions(dem_engine INTERFACE "$<INSTALL_INTERFACE:EIGEN_NO_DEBUG;EIGEN_DONT_VECTORIZE>")
if(DEM_ARCH_FLAGS)
  target_compile_options(dem_engine INTERFACE "$<INSTALL_INTERFACE:${DEM_ARCH_FLAGS}>")
endif()
if(DEM_USES_DDS)
  # idlc_generate's interface target only carries the generated sources
  # that dem_idl_dds compiles; what users of the library need is Cyclone.
  set_property(TARGET dem_idl_dds PROPERTY INTERFACE_LINK_LIBRARIES CycloneDDS::ddsc)
endif()
install(TARGETS ${export_targets} EXPORT demTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
  LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR} COMPONENT development
  INCLUDES DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY engine/include/ analysis/include/ io/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}
        COMPONENT development)
install(FILES ${PROJECT_BINARY_DIR}/idl/dem/case.pb.h ${PROJECT_BINARY_DIR}/idl/dem/snapshot.pb.h
              ${PROJECT_BINARY_DIR}/generated/version/dem/version.h
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/dem COMPONENT development)
if(DEM_USES_DDS)
  install(DIRECTORY dds/include/ protocol/include/ ${PROJECT_BINARY_DIR}/protocol/generated/include/
          DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT development)
  if(TARGET dem_client)
    install(DIRECTORY clients/cpp/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR} COMPONENT development)
  endif()
endif()
set(config_dir ${CMAKE_INSTALL_LIBDIR}/cmake/dem)
install(EXPORT demTargets NAMESPACE dem:: DESTINATION ${config_dir} COMPONENT development)
configure_package_config_file(cmake/demConfig.cmake.in ${PROJECT_BINARY_DIR}/demConfig.cmake
  INSTALL_DESTINATION ${config_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/demConfigVersion.cmake COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/demConfig.cmake ${PROJECT_BINARY_DIR}/demConfigVersion.cmake
        DESTINATION ${config_dir} COMPONENT development)

# --- data and documents --------------------------------------------------
install(DIRECTORY cases config DESTINATION ${CMAKE_INSTALL_DATADIR}/dem COMPONENT runtime)
install(FILES tools/paraview/force_chains.py DESTINATION ${CMAKE_INSTALL_DATADIR}/dem/paraview COMPONENT runtime)
# Sweeps (docs/SWEEPS.md): the task script dem.sweep copies into each sweep, and a
# one-machine Slurm cluster; the DDS configuration for hosts of a real network (DDS.md).
install(PROGRAMS scripts/slurm/dem_sweep_task.sh scripts/slurm/local_cluster.sh
        DESTINATION ${CMAKE_INSTALL_DATADIR}/dem/scripts/slurm COMPONENT runtime)
install(PROGRAMS scripts/dds_network_config.sh DESTINATION ${CMAKE_INSTALL_DATADIR}/dem/scripts COMPONENT runtime)
install(DIRECTORY ros2/dem_interfaces DESTINATION ${CMAKE_INSTALL_DATADIR}/dem/ros2 COMPONENT runtime)
install(FILES README.md LICENSE DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
install(DIRECTORY docs/ DESTINATION ${CMAKE_INSTALL_DOCDIR} COMPONENT runtime)
# Debian's copyright file (machine-readable format 1.0), in each package's
# /usr/share/doc/<package>/, from LICENSE.
file(READ ${PROJECT_SOURCE_DIR}/LICENSE license_text)
string(REGEX MATCH "Copyright \\(c\\) [^\n]*" copyright_line "${license_text}")
string(REGEX REPLACE "^Copyright \\(c\\) " "" copyright_holders "${copyright_line}")
string(REGEX REPLACE "^MIT License\n\n[^\n]*\n\n" "" license_body "${license_text}")
string(REGEX REPLACE "\n\n" "\n.\n" license_body "${license_body}")
string(REGEX REPLACE "\n" "\n " license_body "${license_body}")
string(REGEX REPLACE " $" "" license_body "${license_body}")
file(WRITE ${PROJECT_BINARY_DIR}/copyright
"Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/
Upstream-Name: dem
Upstream-Contact: dem maintainers <dem@example.org>

Files: *
Copyright: ${copyright_holders}
License: Expat
 ${license_body}")
install(FILES ${PROJECT_BINARY_DIR}/copyright DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/dem COMPONENT runtime)
install(FILES ${PROJECT_BINARY_DIR}/copyright DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/dem-dev COMPONENT development)

# --- the Python client -------------------------------------------------
# The package as the build assembled it, except where-things-are: the
# installed dem._build_info names the installed programs and data.
if(TARGET dem_python)
  # Debian's interpreter looks in <prefix>/lib/python3/dist-packages (not the multiarch libdir).
  set(python_dir lib/python3/dist-packages)
  # Paths from the file's own place, so any prefix (and a package's /usr) works.
  file(GENERATE OUTPUT ${PROJECT_BINARY_DIR}/install/_build_info.py CONTENT
"# Written by CMake (cmake/install.cmake): where the installed package's programs and data are,
# found from this file's place, <prefix>/${python_dir}/dem/_build_info.py.
import pathlib as _pathlib
_PREFIX = _pathlib.Path(__file__).resolve().parents[4]
VERSION = \"${PROJECT_VERSION}\"
PYTHON = \"/usr/bin/python3\"
PYTHON_VERSION = \"${DEM_PYTHON_VERSION}\"
SERVER_PROGRAM = str(_PREFIX / \"${CMAKE_INSTALL_BINDIR}\" / \"dem_server\")
DEMCTL_PROGRAM = str(_PREFIX / \"${CMAKE_INSTALL_BINDIR}\" / \"demctl\")
RUN_PROGRAM = str(_PREFIX / \"${CMAKE_INSTALL_BINDIR}\" / \"dem_run\")
LOOPBACK_CONFIG = str(_PREFIX / \"${CMAKE_INSTALL_DATADIR}\" / \"dem\" / \"config\" / \"cyclonedds-loopback.xml\")
SOURCE_DIR = str(_PREFIX / \"${CMAKE_INSTALL_DATADIR}\" / \"dem\")
")
  install(DIRECTORY ${DEM_PYTHON_PATH}/dem DESTINATION ${python_dir} COMPONENT runtime
    PATTERN "_build_info.py" EXCLUDE PATTERN "__pycache__" EXCLUDE)
  install(FILES ${PROJECT_BINARY_DIR}/install/_build_info.py DESTINATION ${python_dir}/dem COMPONENT runtime)
endif()

# --- the Debian packages -------------------------------------------------
# dem: the programs, the Python client, the cases, the documents (what
# the image installs); dem-dev: what find_package(dem) needs, with the
# Debian -dev packages its configuration finds (demConfig.cmake.in).
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME dem)
set(CPACK_PACKAGE_VENDOR "the dem contributors")
set(CPACK_PACKAGE_CONTACT "dem maintainers <dem@example.org>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "discrete element method engine for granular mechanics, with a DDS service")
set(CPACK_PACKAGE_DESCRIPTION
  "dem_run runs DEM cases headless (Cundall & Strack's BALL, Randall's Hertz-Mindlin contacts, Miyata's particle \
shapes); dem_server runs them as a service over Cyclone DDS, driven by demctl, the C++ client library or the \
Python client (package dem); dem_vtk writes ParaView files.")
set(CPACK_RESOURCE_FILE_LICENSE ${PROJECT_SOURCE_DIR}/LICENSE)
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEB_COMPONENT_INSTALL ON)
set(CPACK_COMPONENTS_ALL runtime development)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_NAME dem)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_NAME dem-dev)
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_SECTION libdevel)
set(CPACK_COMPONENT_DEVELOPMENT_DESCRIPTION
  "dem's libraries, headers and CMake configuration for find_package(dem): dem::engine, dem::analysis, dem::io, \
dem::dds, dem::protocol, dem::client (C++20).")
# The shared libraries the programs and the extension link (Cyclone DDS,
# Protocol Buffers, spdlog, OpenMP, ...) from dpkg-shlibdeps; the Python
# client's own imports by hand.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_RUNTIME_PACKAGE_DEPENDS "python3 (>= 3.11), python3-numpy, python3-protobuf")
# The plots, and the bridge's web server and charts (python3 -m dem.bridge).
set(CPACK_DEBIAN_RUNTIME_PACKAGE_RECOMMENDS "python3-matplotlib, python3-websockets, libjs-chart.js")
# demConfig.cmake's find_dependency calls: Eigen3, Protobuf (and the
# headers protoc made for its version), OpenSSL, CycloneDDS; OpenMP comes
# with the compiler (g++'s libgomp).
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_DEPENDS
  "dem (= ${PROJECT_VERSION}), libeigen3-dev (>= 3.4), libprotobuf-dev, libssl-dev, cyclonedds-dev")
set(CPACK_DEBIAN_DEVELOPMENT_PACKAGE_RECOMMENDS "cmake (>= 3.25), g++ (>= 4:12)")
include(CPack)
