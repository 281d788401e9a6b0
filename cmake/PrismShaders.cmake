# prism_add_shaders(): runs prism-shaderc at build time and makes a static library
# target holding the generated catalogue: a small header of declarations and a
# generated .cpp of data beside it, which the library compiles (no extra CMake needed).
#
#   prism_add_shaders(<target>
#     SOURCES <stage files...>          # .vert/.tesc/.tese/.geom/.frag/.comp (or directories);
#                                       # same-name files make one program
#     [PROGRAMS NAME=FILE[,FILE...]...] # programs from any stage files (--program; docs/shaderc.md)
#     MODULE_DIRS <dirs...>             # -I, searched in order
#     [HEADER <name.hpp>]               # default <target>.hpp; may contain a subdirectory
#     [NAMESPACE <ns>]                  # default: the target's name (as a C identifier)
#     [CONTRACT <json files...>]        # binding contract(s)
#     [DEFINES NAME[=VALUE]...]         # -D for every stage
#     [VARIANTS SHADER:NAME=VALUE,...]  # emit only these variants of those shaders; a value the
#                                       # axis's #pragma lacks is a configure error listing its values
#     [GLSL_VERSION <n>]                # default 330
#     [TARGETS gl es300 spirv]          # --target: also produce these (docs/targets.md); default gl
#     [WEB <file.js>]                   # --emit-web: the web catalogue for WebGL2 (needs es300 in TARGETS;
#                                       # relative to the current binary dir; docs/targets.md, "Web catalogue")
#     [CLIENT opengl|vulkan]            # default opengl; vulkan stores SPIR-V (docs/shaderc.md, "Clients")
#     [TARGET_ENV vulkan1.x])           # CLIENT vulkan only: vulkan1.0 ... vulkan1.3, default vulkan1.2
#
#   target_link_libraries(app PRIVATE <target>)   # then #include "<name.hpp>"
#
# Beside <name.hpp> it writes <name>_sources.hpp (at configure time): <ns>::kSourceTree,
# the folders, contract files and defines above as absolute paths, which hot reload
# needs (prism/catalog/source_tree.hpp, docs/hot-reload.md). The catalogue's own files
# stay free of absolute paths.
#
# The command's primary output is a stamp file; the header and the data file are
# byproducts that the tool rewrites only when their content changes, so touching a
# module re-runs the tool (and only for the catalogues that read it, via the depfile)
# and recompiles the one data file; code including the header recompiles only when a
# shader or module is added, removed or renamed. Works with Ninja and Unix Makefiles
# (CMake >= 3.20).
include_guard(GLOBAL)
if(CMAKE_VERSION VERSION_LESS 3.20)
  message(FATAL_ERROR "prism_add_shaders() needs CMake 3.20 or newer (DEPFILE with Makefile generators)")
endif()

# A function runs with the policies recorded where it is defined, not those of the
# caller: pin them so that a consumer with an older cmake_minimum_required() still gets
# CMP0116 NEW. With OLD, Ninja reads the depfile untransformed; its target is then the
# stamp's absolute path, which does not match the build.ninja output, so Ninja treats
# the stamp as always dirty and re-runs prism-shaderc on every build.
cmake_policy(PUSH)
cmake_policy(VERSION 3.20...3.25)

# The library type of generated catalogues: STATIC (default) or SHARED. A shared catalogue
# exports one symbol, kCatalog, which a module edit never changes; with
# CMAKE_LINK_DEPENDS_NO_SHARED ON, a module edit then relinks only the catalogue's own
# library, not every program that uses it. Prism's own build does both (top-level
# CMakeLists.txt; docs/shaderc.md, "The edit loop").
if(NOT DEFINED PRISM_SHADERS_LIBRARY_TYPE)
  set(PRISM_SHADERS_LIBRARY_TYPE STATIC)
endif()

# Records that catalogue `owner` defines <ns>::kCatalog; a second catalogue with the same
# namespace would link (a shared and a static kCatalog) and run with the wrong data, so it
# is a configure error. PrismConfig.cmake claims the namespaces of Prism's installed ones.
function(_prism_claim_catalog_namespace ns owner)
  string(MAKE_C_IDENTIFIER "${ns}" key)
  get_property(taken GLOBAL PROPERTY PRISM_CATALOG_NAMESPACE_${key})
  if(taken AND NOT taken STREQUAL owner)
    message(FATAL_ERROR "prism_add_shaders(${owner}): NAMESPACE ${ns} is already the namespace of the catalogue "
                        "${taken}, so both would define ${ns}::kCatalog; give ${owner} a NAMESPACE of its own, "
                        "or leave NAMESPACE out to take the target's name")
  endif()
  set_property(GLOBAL PROPERTY PRISM_CATALOG_NAMESPACE_${key} ${owner})
endfunction()

# `out` = a C++ expression for a span of `type` holding `items` (each already a C++
# initialiser): a named inline array, or an empty span (a zero-size array is ill-formed).
function(_prism_cxx_span out type name)
  if(NOT ARGN)
    set(${out} "std::span<const ${type}>{}" PARENT_SCOPE)
    return()
  endif()
  list(JOIN ARGN ",\n    " body)
  set(${out} "${name}" PARENT_SCOPE)
  set(_prism_arrays "${_prism_arrays}inline constexpr ${type} ${name}[] = {\n    ${body},\n};\n" PARENT_SCOPE)
endfunction()

# Writes <header stem>_sources.hpp: the catalogue's prism-shaderc command line as
# prism::catalog::SourceTree <ns>::kSourceTree (prism/catalog/source_tree.hpp), for hot
# reload. It holds the absolute paths the catalogue's own files leave out, and is
# rewritten only when they change (at configure time).
function(_prism_write_source_tree file ns base_dir module_dirs contracts defines)
  set(_prism_arrays "")
  set(dirs "")
  foreach(dir IN LISTS module_dirs)
    list(APPEND dirs "R\"prism(${dir})prism\"")
  endforeach()
  set(files "")
  foreach(contract IN LISTS contracts)
    list(APPEND files "R\"prism(${contract})prism\"")
  endforeach()
  set(defs "")
  foreach(def IN LISTS defines)  # prism-shaderc's -D NAME[=VALUE]: VALUE "1" when left out
    string(FIND "${def}" "=" eq)
    if(eq EQUAL -1)
      list(APPEND defs "{\"${def}\", \"1\"}")
    else()
      string(SUBSTRING "${def}" 0 ${eq} name)
      math(EXPR after "${eq} + 1")
      string(SUBSTRING "${def}" ${after} -1 value)
      list(APPEND defs "{\"${name}\", R\"prism(${value})prism\"}")
    endif()
  endforeach()
  _prism_cxx_span(dirs_expr "std::string_view" kSourceModuleDirs ${dirs})
  _prism_cxx_span(files_expr "std::string_view" kSourceContractFiles ${files})
  _prism_cxx_span(defs_expr "prism::catalog::Define" kSourceDefines ${defs})
  string(CONCAT text "// Generated by prism_add_shaders(). Where catalogue ${ns} was built from, for hot reload\n"
           "// (prism/catalog/source_tree.hpp, prism/render/shader_watcher.hpp). Absolute paths of this machine.\n"
           "#pragma once\n\n#include <span>\n#include <string_view>\n\n"
           "#include <prism/catalog/source_tree.hpp>\n\nnamespace ${ns} {\n\n${_prism_arrays}"
           "inline constexpr prism::catalog::SourceTree kSourceTree{\"${ns}\", R\"prism(${base_dir})prism\", "
           "${dirs_expr}, ${files_expr}, ${defs_expr}};\n\n}  // namespace ${ns}\n")
  file(CONFIGURE OUTPUT ${file} CONTENT "${text}" @ONLY)
endfunction()

# The values of each variant axis that the stage files and the .glsl directly in the module
# dirs declare (`#pragma prism variant NAME [VALUE...]`; no values: 0 and 1), as variables
# <prefix>_<NAME> in the caller and the axis names in <prefix>_AXES.
function(_prism_declared_variant_axes prefix files module_dirs)
  foreach(dir IN LISTS module_dirs)
    file(GLOB modules ${dir}/*.glsl)
    list(APPEND files ${modules})
  endforeach()
  set(axes "")
  foreach(file IN LISTS files)
    if(NOT EXISTS ${file})
      continue()  # prism-shaderc reports a missing stage file at build time
    elseif(IS_DIRECTORY ${file})
      file(GLOB_RECURSE in_dir ${file}/*.vert ${file}/*.frag ${file}/*.geom ${file}/*.comp ${file}/*.tesc
                               ${file}/*.tese ${file}/*.glsl)
      set(files_here ${in_dir})
    else()
      set(files_here ${file})
    endif()
    foreach(f IN LISTS files_here)
      file(STRINGS ${f} pragmas REGEX "^[ \t]*#[ \t]*pragma[ \t]+prism[ \t]+variant[ \t]")
      foreach(line IN LISTS pragmas)
        string(REGEX REPLACE "//.*$" "" line "${line}")
        string(REGEX REPLACE "^[ \t]*#[ \t]*pragma[ \t]+prism[ \t]+variant[ \t]+" "" line "${line}")
        string(REGEX MATCHALL "[^ \t]+" words "${line}")
        if(NOT words)
          continue()  # a pragma without an axis name: prism-shaderc reports it at its line
        endif()
        list(POP_FRONT words axis)
        if(NOT words)
          set(words 0 1)
        endif()
        if(NOT axis IN_LIST axes)
          list(APPEND axes ${axis})
          set(${prefix}_${axis} ${words} PARENT_SCOPE)
        endif()
      endforeach()
    endforeach()
  endforeach()
  set(${prefix}_AXES ${axes} PARENT_SCOPE)
endfunction()

# A VARIANTS entry SHADER:NAME=VALUE,... whose axis a stage or module declares with other
# values is a configure error (CMake's call stack names the caller's line) listing the
# values. An axis declared nowhere that CMake reads (say in a module included by a
# relative path) is left to prism-shaderc, which reports it with "did you mean".
function(_prism_check_variant_filters target filters files module_dirs)
  if(NOT filters)
    return()
  endif()
  _prism_declared_variant_axes(declared "${files}" "${module_dirs}")
  foreach(filter IN LISTS filters)
    if(NOT filter MATCHES "^([^:]+):(.+)$")
      message(FATAL_ERROR "prism_add_shaders(${target}): VARIANTS ${filter}: expected SHADER:NAME=VALUE[,NAME=VALUE...] "
                          "(SHADER may be *)")
    endif()
    string(REPLACE "," ";" assignments "${CMAKE_MATCH_2}")
    foreach(assignment IN LISTS assignments)
      if(NOT assignment MATCHES "^([A-Za-z_][A-Za-z0-9_]*)=(.+)$")
        message(FATAL_ERROR "prism_add_shaders(${target}): VARIANTS ${filter}: '${assignment}' is not NAME=VALUE")
      endif()
      set(axis ${CMAKE_MATCH_1})
      set(value ${CMAKE_MATCH_2})
      if(axis IN_LIST declared_AXES AND NOT value IN_LIST declared_${axis})
        list(JOIN declared_${axis} ", " values)
        message(FATAL_ERROR "prism_add_shaders(${target}): VARIANTS ${filter}: the variant axis ${axis} takes "
                            "${values}, not ${value}")
      endif()
    endforeach()
  endforeach()
endfunction()

function(prism_add_shaders target)
  cmake_parse_arguments(PARSE_ARGV 1 PAS "" "HEADER;NAMESPACE;GLSL_VERSION;CLIENT;TARGET_ENV;WEB"
                        "SOURCES;PROGRAMS;MODULE_DIRS;DEFINES;CONTRACT;VARIANTS;TARGETS")
  if(PAS_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "prism_add_shaders(${target}): unknown arguments: ${PAS_UNPARSED_ARGUMENTS}")
  endif()
  if(NOT PAS_SOURCES AND NOT PAS_PROGRAMS)
    message(FATAL_ERROR "prism_add_shaders(${target}): give the shader stage files with SOURCES or PROGRAMS")
  endif()
  if(NOT TARGET Prism::shaderc)
    message(FATAL_ERROR "prism_add_shaders(${target}): Prism::shaderc is unknown; add_subdirectory(prism) "
                        "or find_package(Prism) first")
  endif()
  if(NOT PAS_HEADER)
    set(PAS_HEADER ${target}.hpp)
  endif()
  if(NOT PAS_NAMESPACE)
    # Target names are unique in a build, so two catalogues in one program never share
    # the symbol <ns>::kCatalog (Prism's own is prism::shaders, in libprism_shaders).
    string(MAKE_C_IDENTIFIER "${target}" PAS_NAMESPACE)
  endif()
  _prism_claim_catalog_namespace(${PAS_NAMESPACE} ${target})

  set(gen_dir ${CMAKE_CURRENT_BINARY_DIR}/${target}_generated)
  set(header ${gen_dir}/${PAS_HEADER})
  string(REGEX REPLACE "\\.[^./]*$" "" data ${header})
  set(data ${data}.cpp)  # written by prism-shaderc beside the header
  if(data STREQUAL header)
    message(FATAL_ERROR "prism_add_shaders(${target}): HEADER ${PAS_HEADER} must not end in .cpp")
  endif()
  string(REGEX REPLACE "\\.[^./]*$" "_sources.hpp" source_tree ${header})
  set(stamp ${CMAKE_CURRENT_BINARY_DIR}/${target}.stamp)
  set(depfile ${CMAKE_CURRENT_BINARY_DIR}/${target}.d)

  set(args -o ${header} --depfile ${depfile} --stamp ${stamp} --namespace ${PAS_NAMESPACE}
           --base-dir ${PROJECT_SOURCE_DIR})
  set(depends Prism::shaderc)
  set(sources "")              # a function sees its caller's variables: start these empty
  set(program_stage_files "")
  foreach(src IN LISTS PAS_SOURCES)
    get_filename_component(abs ${src} ABSOLUTE)
    list(APPEND sources ${abs})
    list(APPEND depends ${abs})
  endforeach()
  foreach(program IN LISTS PAS_PROGRAMS)
    if(NOT program MATCHES "^([^=]+)=(.+)$")
      message(FATAL_ERROR "prism_add_shaders(${target}): PROGRAMS ${program}: expected NAME=FILE[,FILE...]")
    endif()
    set(program_name ${CMAKE_MATCH_1})
    string(REPLACE "," ";" program_files "${CMAKE_MATCH_2}")
    set(program_arg "")
    foreach(file IN LISTS program_files)
      get_filename_component(abs ${file} ABSOLUTE)
      list(APPEND depends ${abs})
      list(APPEND program_stage_files ${abs})
      string(APPEND program_arg ",${abs}")
    endforeach()
    string(SUBSTRING "${program_arg}" 1 -1 program_arg)
    list(APPEND args --program "${program_name}=${program_arg}")
  endforeach()
  set(module_dirs "")
  foreach(dir IN LISTS PAS_MODULE_DIRS)
    get_filename_component(abs ${dir} ABSOLUTE)
    list(APPEND args -I ${abs})
    list(APPEND module_dirs ${abs})
    # The catalogue lists every .glsl below each module dir, but the depfile names files
    # only: depend on the directory too, whose mtime changes when a module is added,
    # removed or renamed in it, so the module list in the header cannot go stale.
    # (Not its sub-directories: a module dir may hold a build tree, whose directories
    # change on every build.)
    list(APPEND depends ${abs})
  endforeach()
  set(contracts "")
  foreach(contract IN LISTS PAS_CONTRACT)
    get_filename_component(abs ${contract} ABSOLUTE)
    list(APPEND args --contract ${abs})
    list(APPEND contracts ${abs})
    list(APPEND depends ${abs})
  endforeach()
  foreach(def IN LISTS PAS_DEFINES)
    list(APPEND args -D ${def})
  endforeach()
  _prism_check_variant_filters(${target} "${PAS_VARIANTS}" "${sources};${program_stage_files}" "${module_dirs}")
  foreach(variant IN LISTS PAS_VARIANTS)
    list(APPEND args --variant ${variant})
  endforeach()
  if(PAS_GLSL_VERSION)
    list(APPEND args --glsl-version ${PAS_GLSL_VERSION})
  endif()
  if(PAS_CLIENT)
    if(NOT PAS_CLIENT MATCHES "^(opengl|vulkan)$")
      message(FATAL_ERROR "prism_add_shaders(${target}): CLIENT ${PAS_CLIENT} is none of opengl, vulkan")
    endif()
    list(APPEND args --client ${PAS_CLIENT})
  endif()
  if(PAS_TARGET_ENV)
    if(NOT PAS_CLIENT STREQUAL "vulkan")
      message(FATAL_ERROR "prism_add_shaders(${target}): TARGET_ENV ${PAS_TARGET_ENV} needs CLIENT vulkan")
    endif()
    list(APPEND args --target-env ${PAS_TARGET_ENV})
  endif()
  if(PAS_TARGETS)
    string(REPLACE ";" "," target_list "${PAS_TARGETS}")
    list(APPEND args --target ${target_list})
  endif()

  set(web "")
  if(PAS_WEB)
    get_filename_component(web ${PAS_WEB} ABSOLUTE BASE_DIR ${CMAKE_CURRENT_BINARY_DIR})
    list(APPEND args --emit-web ${web})
  endif()

  _prism_write_source_tree(${source_tree} ${PAS_NAMESPACE} ${PROJECT_SOURCE_DIR} "${module_dirs}" "${contracts}"
                           "${PAS_DEFINES}")

  add_custom_command(
    OUTPUT ${stamp}
    BYPRODUCTS ${header} ${data} ${web}
    COMMAND Prism::shaderc ${args} ${sources}
    DEPENDS ${depends}
    DEPFILE ${depfile}
    COMMENT "prism-shaderc: generating ${PAS_HEADER}"
    VERBATIM)
  add_custom_target(${target}_generate DEPENDS ${stamp})
  add_library(${target} ${PRISM_SHADERS_LIBRARY_TYPE} ${data})
  add_dependencies(${target} ${target}_generate)
  # UNITY_BUILD OFF under CMAKE_UNITY_BUILD too: a module edit compiles the data file itself,
  # one unit, not a unity file that includes it.
  set_target_properties(${target} PROPERTIES POSITION_INDEPENDENT_CODE ON UNITY_BUILD OFF)
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${gen_dir}>)
  target_link_libraries(${target} PUBLIC Prism::catalog)
  set_target_properties(${target} PROPERTIES PRISM_HEADER ${header} PRISM_NAMESPACE ${PAS_NAMESPACE}
                                             PRISM_WEB "${web}")
  if(COMMAND prism_set_layer)  # inside Prism's own build: catalogues are CPU-layer data
    prism_set_layer(${target} cpu)
  endif()
endfunction()

cmake_policy(POP)
