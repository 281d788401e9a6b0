# prism_library(): declares one runtime library the way every Prism library is laid out:
#   runtime/<dir>/include/prism/<name>/*.hpp   public headers (include path = namespace)
#   runtime/<dir>/src/*.cpp                    sources and private headers
# It records the library's LAYER (cpu, gl, render, systems, scenes) for the layering check
# (scripts/check_layers.py, docs/architecture.md), exports it as Prism::<EXPORT_NAME> and
# installs it with its headers when PRISM_INSTALL is on.
#
#   prism_library(prism_view EXPORT_NAME view LAYER cpu
#     SOURCES src/camera.cpp PUBLIC glm::glm)
include_guard(GLOBAL)
include(GNUInstallDirs)

set(PRISM_LAYERS cpu gl render systems scenes apps)

function(prism_library name)
  cmake_parse_arguments(ARG "" "EXPORT_NAME;LAYER" "SOURCES;PUBLIC;PRIVATE" ${ARGN})
  if(NOT ARG_LAYER IN_LIST PRISM_LAYERS)
    message(FATAL_ERROR "prism_library(${name}): LAYER must be one of ${PRISM_LAYERS}, got '${ARG_LAYER}'")
  endif()
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name}
    PUBLIC $<BUILD_INTERFACE:${CMAKE_CURRENT_SOURCE_DIR}/include> $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>
    PRIVATE ${CMAKE_CURRENT_SOURCE_DIR}/src)
  target_link_libraries(${name} PUBLIC ${ARG_PUBLIC} PRIVATE ${ARG_PRIVATE})
  target_compile_features(${name} PUBLIC cxx_std_20)
  set_target_properties(${name} PROPERTIES POSITION_INDEPENDENT_CODE ON EXPORT_NAME ${ARG_EXPORT_NAME})
  prism_set_layer(${name} ${ARG_LAYER})
  add_library(Prism::${ARG_EXPORT_NAME} ALIAS ${name})
  if(NOT PRISM_INSTALL)
    return()
  endif()
  install(TARGETS ${name} EXPORT PrismTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR})
  if(EXISTS ${CMAKE_CURRENT_SOURCE_DIR}/include)
    install(DIRECTORY ${CMAKE_CURRENT_SOURCE_DIR}/include/ DESTINATION ${CMAKE_INSTALL_INCLUDEDIR})
  endif()
endfunction()

# Records a target's layer for the layering check (libraries, catalogues and apps alike).
function(prism_set_layer target layer)
  set_property(TARGET ${target} PROPERTY PRISM_LAYER ${layer})
  set_property(GLOBAL APPEND PROPERTY PRISM_LAYERED_TARGETS ${target})
endfunction()

# Writes <build>/prism_link_graph.txt: one line "target layer dep1 dep2 ..." per layered
# target, with its direct link dependencies that are themselves layered targets.
# scripts/check_layers.py reads it; call once at the end of the top-level CMakeLists.txt.
function(prism_write_link_graph)
  get_property(targets GLOBAL PROPERTY PRISM_LAYERED_TARGETS)
  set(lines "")
  foreach(t IN LISTS targets)
    get_target_property(layer ${t} PRISM_LAYER)
    get_target_property(type ${t} TYPE)
    set(deps "")
    set(link "")
    if(NOT type STREQUAL "INTERFACE_LIBRARY")
      get_target_property(l ${t} LINK_LIBRARIES)
      if(l)
        list(APPEND link ${l})
      endif()
    endif()
    get_target_property(il ${t} INTERFACE_LINK_LIBRARIES)
    if(il)
      list(APPEND link ${il})
    endif()
    foreach(d IN LISTS link)
      string(REGEX REPLACE "^\\$<LINK_ONLY:(.*)>$" "\\1" d "${d}")
      if(TARGET ${d})
        get_target_property(aliased ${d} ALIASED_TARGET)
        if(aliased)
          set(d ${aliased})
        endif()
        if(d IN_LIST targets AND NOT d IN_LIST deps)
          list(APPEND deps ${d})
        endif()
      endif()
    endforeach()
    list(SORT deps)
    list(JOIN deps " " deps_text)
    string(APPEND lines "${t} ${layer} ${deps_text}\n")
  endforeach()
  file(WRITE ${PROJECT_BINARY_DIR}/prism_link_graph.txt "${lines}")
endfunction()

# Installs one of Prism's own generated catalogues (a prism_add_shaders() target: a static
# library of the generated data) with its header, so installed runtime libraries that use it can be linked by other projects.
function(prism_install_catalog target export_name)
  get_target_property(header ${target} PRISM_HEADER)
  get_target_property(gen_dirs ${target} INTERFACE_INCLUDE_DIRECTORIES)
  get_filename_component(header_dir ${header} DIRECTORY)
  string(REGEX REPLACE "^\\$<BUILD_INTERFACE:(.*)>$" "\\1" gen_dir "${gen_dirs}")
  file(RELATIVE_PATH header_rel ${gen_dir} ${header_dir})
  target_include_directories(${target} PUBLIC $<INSTALL_INTERFACE:${CMAKE_INSTALL_INCLUDEDIR}>)
  set_target_properties(${target} PROPERTIES EXPORT_NAME ${export_name})
  set_property(TARGET ${target} APPEND PROPERTY EXPORT_PROPERTIES PRISM_NAMESPACE)  # claimed by PrismConfig.cmake
  if(NOT PRISM_INSTALL)
    return()
  endif()
  install(TARGETS ${target} EXPORT PrismTargets ARCHIVE DESTINATION ${CMAKE_INSTALL_LIBDIR}
                                               LIBRARY DESTINATION ${CMAKE_INSTALL_LIBDIR})
  install(FILES ${header} DESTINATION ${CMAKE_INSTALL_INCLUDEDIR}/${header_rel})
endfunction()
