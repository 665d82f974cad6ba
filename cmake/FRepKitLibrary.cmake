# frepkit_add_library(<Name> [STATIC] INCLUDE_ROOT <dir> [SOURCES ...] [PUBLIC_HEADERS ...])
#
# One rule for every plain C++ library of FRepKit (the engine and the multimedia libraries; the
# VTK modules get the same from vtk_module_build): target FRepKit<Name>, alias FRepKit::<Name>,
# file libFRepKit<Name>.so.<version> with SOVERSION <major>, position-independent, C++20.
#
# The public/private line: PUBLIC_HEADERS (paths relative to the current folder) form the
# target's HEADERS file set, rooted at INCLUDE_ROOT — the folder users include from, so that
# `#include "Compiler/model.h"` (engine, root FRep/) or `#include "Render/mesh_renderer.h"` (root
# Multimedia/) reads the same in the build tree and in an installed tree. Every other header is
# private: reachable from inside the project's build, never installed. More public headers can be
# added from subfolders with frepkit_add_public_headers().
function(frepkit_add_library name)
  cmake_parse_arguments(PARSE_ARGV 1 arg "STATIC" "INCLUDE_ROOT" "SOURCES;PUBLIC_HEADERS")
  if(NOT arg_INCLUDE_ROOT)
    message(FATAL_ERROR "frepkit_add_library(${name}): INCLUDE_ROOT is required")
  endif()
  set(target FRepKit${name})
  if(arg_STATIC)
    add_library(${target} STATIC)
  else()
    add_library(${target})
  endif()
  add_library(FRepKit::${name} ALIAS ${target})
  set_target_properties(${target} PROPERTIES
    OUTPUT_NAME FRepKit${name}
    VERSION ${PROJECT_VERSION}
    SOVERSION ${PROJECT_VERSION_MAJOR}
    POSITION_INDEPENDENT_CODE ON
    EXPORT_NAME ${name})
  target_compile_features(${target} PUBLIC cxx_std_20)
  # The whole include root is visible inside the build (tests reach private headers); the file
  # set below is what an installation carries.
  target_include_directories(${target} PUBLIC $<BUILD_INTERFACE:${arg_INCLUDE_ROOT}>)
  target_sources(${target} PUBLIC FILE_SET HEADERS BASE_DIRS "${arg_INCLUDE_ROOT}")
  if(arg_SOURCES)
    target_sources(${target} PRIVATE ${arg_SOURCES})
  endif()
  if(arg_PUBLIC_HEADERS)
    frepkit_add_public_headers(${target} ${arg_PUBLIC_HEADERS})
  endif()
  # Installed with the public headers only (the file set), into the one export set of the package
  # (cmake/FRepKitInstall.cmake); the VTK modules join the same set through vtk_module_build.
  install(TARGETS ${target} EXPORT FRepKitTargets
    LIBRARY DESTINATION lib
    ARCHIVE DESTINATION lib
    RUNTIME DESTINATION bin
    FILE_SET HEADERS DESTINATION include/frepkit)
  set_property(GLOBAL APPEND PROPERTY FREPKIT_PLAIN_LIBRARIES ${target})
endfunction()

# frepkit_add_public_headers(<target> headers...): headers (relative to the current folder) that
# are part of <target>'s installed API.
function(frepkit_add_public_headers target)
  target_sources(${target} PUBLIC FILE_SET HEADERS FILES ${ARGN})
endfunction()

# frepkit_set_module_soversion(<VTK modules...>): the library rule for VTK modules. vtk_module_build
# skips `SOVERSION 0` (it tests the value, and 0 is false in CMake), which leaves the whole
# version in the SONAME (libFRepKitSources.so.0.1.0); set it here so every FRepKit library's
# SONAME is lib<Name>.so.<major>.
function(frepkit_set_module_soversion)
  foreach(module IN LISTS ARGN)
    get_target_property(real_target ${module} ALIASED_TARGET)
    if(NOT real_target)
      set(real_target ${module})
    endif()
    set_target_properties(${real_target} PROPERTIES SOVERSION ${PROJECT_VERSION_MAJOR})
  endforeach()
endfunction()
