# Installs prism-shaderc, the catalogue types, the modules with their binding contract,
# the web runtime (prism_web.js) and the CMake helper, so that another project can
# `find_package(Prism)` and call prism_add_shaders(). Prism_MODULE_DIR and Prism_CONTRACT point
# at the installed modules, Prism_WEB_RUNTIME at the installed prism_web.js.
include(GNUInstallDirs)
include(CMakePackageConfigHelpers)

set_target_properties(prism-shaderc PROPERTIES EXPORT_NAME shaderc)
set_target_properties(prism_catalog PROPERTIES EXPORT_NAME catalog)
install(TARGETS prism-shaderc prism_catalog prism_io prism_hash prism_shaderc_lib EXPORT PrismTargets
        RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR} ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
# The foundation's headers (prism/catalog, prism/io, prism/hash) and the tool's public API (prism/shaderc).
install(DIRECTORY ${PROJECT_SOURCE_DIR}/foundation/catalog/include/ ${PROJECT_SOURCE_DIR}/foundation/io/include/
                  ${PROJECT_SOURCE_DIR}/foundation/hash/include/ ${PROJECT_SOURCE_DIR}/shaderc_tool/include/
        DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
install(DIRECTORY ${PROJECT_SOURCE_DIR}/modules/ DESTINATION ${CMAKE_INSTALL_DATADIR}/prism/modules)
install(FILES ${PROJECT_SOURCE_DIR}/scripts/web/prism_web.js DESTINATION ${CMAKE_INSTALL_DATADIR}/prism/web)

set(PRISM_CMAKE_DIR ${CMAKE_INSTALL_LIBDIR}/cmake/Prism)
install(EXPORT PrismTargets NAMESPACE Prism:: DESTINATION ${PRISM_CMAKE_DIR})
# PATH_VARS: PrismConfig.cmake.in uses @PACKAGE_CMAKE_INSTALL_DATADIR@, which is empty
# (Prism_MODULE_DIR = "/prism/modules") unless the variable is listed here.
configure_package_config_file(${PROJECT_SOURCE_DIR}/cmake/PrismConfig.cmake.in
  ${PROJECT_BINARY_DIR}/PrismConfig.cmake INSTALL_DESTINATION ${PRISM_CMAKE_DIR}
  PATH_VARS CMAKE_INSTALL_DATADIR)
write_basic_package_version_file(${PROJECT_BINARY_DIR}/PrismConfigVersion.cmake
  COMPATIBILITY SameMinorVersion)
install(FILES ${PROJECT_BINARY_DIR}/PrismConfig.cmake ${PROJECT_BINARY_DIR}/PrismConfigVersion.cmake
              ${PROJECT_SOURCE_DIR}/cmake/PrismShaders.cmake
        DESTINATION ${PRISM_CMAKE_DIR})
if(PRISM_BUILD_RUNTIME)
  include(${PROJECT_SOURCE_DIR}/cmake/PrismPackaging.cmake)
endif()
