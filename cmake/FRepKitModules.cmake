# The VTK modules of FRepKit (see DESIGN.md): each folder with a vtk.module file is scanned and
# built against ParaView's VTK. Included after enable_testing() so that module tests register
# with ctest (test names: <module>Cxx-<Test>, e.g. FRepKit::SourcesCxx-TestFRepObject).
set(_frepkit_module_files)
foreach(_frepkit_module_dir IN ITEMS Sources Filters IO Mapping)
  if(EXISTS "${PROJECT_SOURCE_DIR}/${_frepkit_module_dir}/vtk.module")
    list(APPEND _frepkit_module_files "${PROJECT_SOURCE_DIR}/${_frepkit_module_dir}/vtk.module")
  endif()
endforeach()

vtk_module_scan(
  MODULE_FILES        ${_frepkit_module_files}
  PROVIDES_MODULES    FREPKIT_VTK_MODULES
  ENABLE_TESTS        ${FREPKIT_BUILD_TESTING}
  WANT_BY_DEFAULT     ON
  HIDE_MODULES_FROM_CACHE ON)

vtk_module_build(
  MODULES             ${FREPKIT_VTK_MODULES}
  PACKAGE             FRepKit
  # Installed (cmake/FRepKitInstall.cmake): the libraries, the modules' class headers
  # (INSTALL_HEADERS below), the export set shared with the plain libraries
  # (FRepKit-targets.cmake) and the module properties.
  INSTALL_EXPORT      FRepKitTargets
  VERSION             ${PROJECT_VERSION}
  SOVERSION           ${PROJECT_VERSION_MAJOR}
  INSTALL_HEADERS     ON
  # Wrapping on: vtk_module_build writes each module's wrap hierarchy (which ParaView's
  # client-server wrapping of the plug-in and the Python wrapping, cmake/FRepKitPython.cmake,
  # read). What cannot be wrapped (engine types) is hidden with VTK_WRAPEXCLUDE / __VTK_WRAP__.
  ENABLE_WRAPPING     ON
  TEST_DIRECTORY_NAME Testing
  # Relative destinations (ParaView's configuration leaves absolute install dirs behind);
  # they also put the libraries in build/lib and the test drivers in build/bin.
  ARCHIVE_DESTINATION lib
  LIBRARY_DESTINATION lib
  RUNTIME_DESTINATION bin
  HEADERS_DESTINATION include/frepkit
  CMAKE_DESTINATION   lib/cmake/frepkit
  LICENSE_DESTINATION share/licenses/frepkit
  HIERARCHY_DESTINATION lib/vtk/hierarchy/frepkit)

frepkit_set_module_soversion(${FREPKIT_VTK_MODULES})

unset(_frepkit_module_dir)
unset(_frepkit_module_files)
