# Prism for projects without CMake, and for Debian: prism.pc for pkg-config (Make, Meson)
# and the package prism-dev (cpack -G DEB). Included by PrismInstall.cmake when the
# runtime is built, so only when PRISM_INSTALL is on. docs/using-prism.md.
include(GNUInstallDirs)

# The static libraries' own dependencies: as their .pc files name them, and as the Debian
# packages that have them; the context backends the build found (runtime/gl/CMakeLists.txt)
# add theirs.
# SPIRV-Tools: the tool's library validates SPIR-V; spirv-cross-c-shared: it reflects SPIR-V;
# vulkan: Prism::render draws through prism::vk too.
set(PRISM_PC_REQUIRES glm libpng tinyobjloader glslang SPIRV-Tools spirv-cross-c-shared vulkan)
set(PRISM_DEB_DEPENDS libglm-dev libpng-dev libtinyobjloader-dev glslang-dev spirv-tools libspirv-cross-c-shared-dev
    nlohmann-json3-dev libgl1-mesa-dri libvulkan-dev mesa-vulkan-drivers)
if(PRISM_GL_HAVE_EGL)
  list(APPEND PRISM_PC_REQUIRES egl)
  list(APPEND PRISM_DEB_DEPENDS libegl-dev)
endif()
if(PRISM_OSMESA_INCLUDE_DIR AND PRISM_OSMESA_LIBRARY)
  list(APPEND PRISM_PC_REQUIRES osmesa)
  list(APPEND PRISM_DEB_DEPENDS libosmesa6-dev)
endif()
if(PRISM_GL_HAVE_GLFW)
  list(APPEND PRISM_PC_REQUIRES glfw3)
  list(APPEND PRISM_DEB_DEPENDS libglfw3-dev)
endif()

# --- pkg-config: prism.pc ---------------------------------------------------------------
# Relocatable: the prefix is found from the .pc file's own folder (${pcfiledir}).
file(RELATIVE_PATH PRISM_PC_PREFIX ${CMAKE_INSTALL_PREFIX}/${CMAKE_INSTALL_LIBDIR}/pkgconfig ${CMAKE_INSTALL_PREFIX})
string(REGEX REPLACE "/$" "" PRISM_PC_PREFIX "${PRISM_PC_PREFIX}")
list(JOIN PRISM_PC_REQUIRES " " PRISM_PC_REQUIRES)
set(PRISM_PC_LIBS -lpthread)  # the tool's library runs its stages on threads
if(CMAKE_DL_LIBS)  # glad opens libGL
  set(PRISM_PC_LIBS "-l${CMAKE_DL_LIBS} ${PRISM_PC_LIBS}")
endif()
configure_file(${PROJECT_SOURCE_DIR}/cmake/prism.pc.in ${PROJECT_BINARY_DIR}/prism.pc @ONLY)
install(FILES ${PROJECT_BINARY_DIR}/prism.pc DESTINATION ${CMAKE_INSTALL_LIBDIR}/pkgconfig)

# --- Debian package: `cpack -G DEB` in the build dir -------------------------------------
# prism-dev_<version>_<arch>.deb: everything `cmake --install` writes, under /usr. Its
# Depends are the -dev packages find_package(Prism) and prism.pc look for, and the Mesa
# drivers the headless context draws with; dpkg-shlibdeps adds the programs' libraries.
# Only Prism's own build packages: a parent project's CPack stays its own.
if(NOT PROJECT_IS_TOP_LEVEL)
  return()
endif()
list(JOIN PRISM_DEB_DEPENDS ", " CPACK_DEBIAN_PACKAGE_DEPENDS)
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "cmake, pkg-config")
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME prism-dev)
set(CPACK_PACKAGE_CONTACT "The Prism authors <prism@example.org>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "GLSL shader toolchain and headless GL runtime (development files)")
set(CPACK_PACKAGE_DESCRIPTION "Prism builds GLSL shaders from modules into C++ catalogues with\n\
its tool prism-shaderc, and draws them headlessly with its runtime libraries.\n\
This package has the tool, the static runtime libraries and their headers,\n\
the GLSL modules with their binding contract, the CMake package\n\
(find_package(Prism)) and prism.pc for pkg-config.")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION libdevel)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_STRIP_FILES ON)
# What lintian asks of every package: a copyright file, a changelog, and, for the shared
# catalogues in /usr/lib, the ldconfig trigger (instead of calling ldconfig in a script).
set(prism_deb_dir ${PROJECT_BINARY_DIR}/debian)
file(WRITE ${prism_deb_dir}/triggers "activate-noawait ldconfig\n")
file(WRITE ${prism_deb_dir}/changelog "prism-dev (${PROJECT_VERSION}) unstable; urgency=medium\n\n"
  "  * Packaged with cpack from Prism's build (docs/using-prism.md).\n\n"
  " -- ${CPACK_PACKAGE_CONTACT}  Fri, 27 Nov 2026 00:00:00 +0000\n")
file(ARCHIVE_CREATE OUTPUT ${prism_deb_dir}/changelog.gz PATHS ${prism_deb_dir}/changelog FORMAT raw
  COMPRESSION GZip COMPRESSION_LEVEL 9 MTIME 0)
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${prism_deb_dir}/triggers)
install(FILES ${PROJECT_SOURCE_DIR}/LICENSE DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/prism-dev RENAME copyright)
install(FILES ${prism_deb_dir}/changelog.gz DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/prism-dev)
include(CPack)
