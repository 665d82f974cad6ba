# The Python package frepkit (Documentation/python.md): the FRepKit VTK modules wrapped with
# VTK's own Python wrapping (vtk_module_wrap_python), against ParaView's vtkmodules, plus the
# package's __init__.py (Wrapping/Python/frepkit). Included from the top-level CMakeLists.txt
# after cmake/FRepKitModules.cmake when FREPKIT_ENABLE_PYTHON is on.
#
# Build tree:   build/lib/python3/dist-packages/frepkit/{__init__.py, FRepKit<Module>.so}
#               (PYTHONPATH=build/lib/python3/dist-packages; the modules find the FRepKit
#               libraries through their build RPATH, build/lib)
# Install tree: <prefix>/lib/python3/dist-packages/frepkit (Debian's python3 path; the modules
#               find <prefix>/lib through the install RPATH $ORIGIN/../../..)

# VTK's Python wrapping: the wrapper tool, WrappingPythonCore and the Python headers. ParaView's
# VTK finds Python3 (Development) itself; without python3-dev that fails here.
find_package(VTK QUIET COMPONENTS Python WrappingPythonCore)
if(NOT TARGET VTK::WrappingPythonCore OR NOT TARGET VTK::WrapPython OR NOT TARGET VTK::Python)
  message(FATAL_ERROR
    "FRepKit's Python wrapping needs ParaView's VTK with Python (Debian: python3-paraview) and "
    "the Python headers (Debian: python3-dev). Install them (Scripts/install-dependencies.sh) "
    "or configure with -DFREPKIT_ENABLE_PYTHON=OFF.")
endif()

set(FREPKIT_PYTHON_DESTINATION "lib/python3/dist-packages"
  CACHE STRING "Where the Python package frepkit goes, relative to the build tree and to CMAKE_INSTALL_PREFIX")
mark_as_advanced(FREPKIT_PYTHON_DESTINATION)
set(FREPKIT_PYTHON_PACKAGE_DIR "${CMAKE_BINARY_DIR}/${FREPKIT_PYTHON_DESTINATION}"
  CACHE INTERNAL "The build tree's directory holding the package frepkit (PYTHONPATH for tests)")

vtk_module_wrap_python(
  MODULES             ${FREPKIT_VTK_MODULES}
  TARGET              FRepKit::FRepKitPython
  WRAPPED_MODULES     _frepkit_python_wrapped
  PYTHON_PACKAGE      "frepkit"
  MODULE_DESTINATION  "${FREPKIT_PYTHON_DESTINATION}"
  LIBRARY_DESTINATION lib
  INSTALL_HEADERS     OFF
  BUILD_STATIC        OFF)

# The package: __init__.py (imports vtkmodules first, then every wrapped module) in the build
# tree next to the modules, and installed with them.
set(_frepkit_python_init "${PROJECT_SOURCE_DIR}/Wrapping/Python/frepkit/__init__.py")
set(_frepkit_python_built "${FREPKIT_PYTHON_PACKAGE_DIR}/frepkit/__init__.py")
add_custom_command(
  OUTPUT  "${_frepkit_python_built}"
  COMMAND "${CMAKE_COMMAND}" -E copy_if_different "${_frepkit_python_init}" "${_frepkit_python_built}"
  DEPENDS "${_frepkit_python_init}"
  COMMENT "Copying the Python package frepkit's __init__.py")
add_custom_target(frepkit_python_package ALL DEPENDS "${_frepkit_python_built}")
install(FILES "${_frepkit_python_init}"
  DESTINATION "${FREPKIT_PYTHON_DESTINATION}/frepkit"
  COMPONENT python)

message(STATUS "FRepKit: Python package frepkit (${_frepkit_python_wrapped}) in "
  "${FREPKIT_PYTHON_PACKAGE_DIR}")

unset(_frepkit_python_init)
unset(_frepkit_python_built)
unset(_frepkit_python_wrapped)
