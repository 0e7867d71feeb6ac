# Install rules: the exact checker as a library for other projects' tests (issue #4).
#
#   find_package(pdr 0.1 REQUIRED)
#   target_link_libraries(my_test PRIVATE pdr::check)
#   #include "check/check.hpp"   // pdr::check::check_arrays(xyz, tets, ...)
#
# Installs the static libraries pdr_check and pdr_geom (exported as pdr::check, pdr::geom)
# with the header-only pdr_mesh (pdr::mesh), the headers they need under include/pdr, the
# `pdr` command, and lib/cmake/pdr/{pdrConfig,pdrConfigVersion,pdrTargets}.cmake. The
# config finds the dependencies again: GMP through pkg-config (gmp, gmpxx), nlohmann_json,
# Threads. tests/oracle builds examples/check-consumer against such an install.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set(pdr_install_include ${CMAKE_INSTALL_INCLUDEDIR}/pdr)
foreach(t pdr_check pdr_geom pdr_mesh)
  # The source tree while building, the installed headers after.
  set_property(TARGET ${t} PROPERTY INTERFACE_INCLUDE_DIRECTORIES
    "$<BUILD_INTERFACE:${PROJECT_SOURCE_DIR}/src>"
    "$<INSTALL_INTERFACE:${pdr_install_include}>")
endforeach()
# A sanitizer build's static libraries need the sanitizer runtimes in whatever links them:
# the installed targets carry the link options (and the compile options, so that the
# consumer's own code agrees on the instrumentation).
if(PDR_SANITIZE)
  target_link_options(pdr_geom INTERFACE -fsanitize=address,undefined)
  target_compile_options(pdr_geom INTERFACE -fsanitize=address,undefined)
endif()
set_target_properties(pdr_check PROPERTIES EXPORT_NAME check)
set_target_properties(pdr_geom PROPERTIES EXPORT_NAME geom)
set_target_properties(pdr_mesh PROPERTIES EXPORT_NAME mesh)

install(TARGETS pdr_check pdr_geom pdr_mesh EXPORT pdrTargets
  ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
  INCLUDES DESTINATION ${pdr_install_include})
install(TARGETS pdr RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} OPTIONAL)

# Headers: the public checker API and everything it includes (geom, mesh).
install(FILES
  src/check/check.hpp src/check/explain.hpp src/check/fields.hpp
  DESTINATION ${pdr_install_include}/check)
install(DIRECTORY src/geom/ DESTINATION ${pdr_install_include}/geom FILES_MATCHING PATTERN "*.hpp")
install(DIRECTORY src/mesh/ DESTINATION ${pdr_install_include}/mesh FILES_MATCHING PATTERN "*.hpp")

set(pdr_cmake_dir ${CMAKE_INSTALL_LIBDIR}/cmake/pdr)
install(EXPORT pdrTargets NAMESPACE pdr:: DESTINATION ${pdr_cmake_dir})
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/pdrConfig.cmake.in
  ${PROJECT_BINARY_DIR}/pdrConfig.cmake INSTALL_DESTINATION ${pdr_cmake_dir})
write_basic_package_version_file(${PROJECT_BINARY_DIR}/pdrConfigVersion.cmake
  VERSION ${PROJECT_VERSION} COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/pdrConfig.cmake ${PROJECT_BINARY_DIR}/pdrConfigVersion.cmake
  DESTINATION ${pdr_cmake_dir})
