# What `cmake --install build --prefix P` installs, and the Debian package (`cpack -G DEB`):
#   P/bin/frepkit, P/bin/FRepStudio            RUNPATH $ORIGIN/../lib
#   P/bin/paraview.conf                        the plugins XMLs the ParaView GUI in P/bin reads (*)
#   P/lib/libFRepKit<Name>.so.<version>        the plain libraries and the VTK modules
#   P/lib/paraview-5.11/plugins/FRepKit/       the ParaView plug-in, frepkit.plugins.xml beside it
#   P/lib/<multiarch>/paraview-5.11/plugins/   links to it: where Debian's ParaView looks (*)
#   (*) only when P is /usr (the .deb) or with FREPKIT_INSTALL_DEBIAN_PARAVIEW_LINKS=ON
#   P/include/frepkit/                         the public headers only
#   P/lib/cmake/frepkit/                       FRepKitConfig.cmake, version, targets, module props
#   P/share/frepkit/examples/                  the models and mappings (frepkit demo finds them)
#   P/share/doc/frepkit/                       README.md and Documentation/
#   P/share/applications, share/icons          FRepStudio's desktop entry and icon
# Installed programs find their data relative to themselves (<bin>/../share/frepkit/examples);
# nothing installed names the build or source tree (checked by
# ctest -R Install.Prefix).
include(CMakePackageConfigHelpers)

set(FREPKIT_INSTALL_CMAKE_DIR lib/cmake/frepkit)
set(FREPKIT_INSTALL_PLUGIN_DIR "lib/paraview-5.11/plugins")
if(FREPKIT_ENABLE_VTK)
  set(FREPKIT_INSTALL_PLUGIN_DIR
    "lib/paraview-${ParaView_VERSION_MAJOR}.${ParaView_VERSION_MINOR}/plugins")
  # Debian's ParaView looks for plug-ins in <prefix>/lib/<multiarch>/paraview-5.11/plugins/<Name>
  # (relative to its executables): the installation links its plug-in folder there.
  set(FREPKIT_PARAVIEW_PLUGIN_LINK_DIR
    "lib/${CMAKE_LIBRARY_ARCHITECTURE}/paraview-${ParaView_VERSION_MAJOR}.${ParaView_VERSION_MINOR}/plugins")
endif()

# --- Programs ----------------------------------------------------------------------------------
install(TARGETS frepkit RUNTIME DESTINATION bin)
if(TARGET FRepStudio)
  install(TARGETS FRepStudio RUNTIME DESTINATION bin)
  install(FILES Apps/FRepStudio/Desktop/frepstudio.desktop DESTINATION share/applications)
  install(FILES Apps/FRepStudio/Desktop/frepstudio.svg
    DESTINATION share/icons/hicolor/scalable/apps)
endif()

# --- Data and documentation --------------------------------------------------------------------
install(DIRECTORY Examples/ DESTINATION share/frepkit/examples USE_SOURCE_PERMISSIONS)
install(FILES README.md DESTINATION share/doc/frepkit)
install(DIRECTORY Documentation/ DESTINATION share/doc/frepkit/Documentation)

# --- The ParaView plug-in in ParaView's own folder ----------------------------------------------
# paraview_plugin_build (ParaViewPlugin/) installs FRepKit/FRepKit.so and frepkit.plugins.xml
# under FREPKIT_INSTALL_PLUGIN_DIR. Only for the Debian package (the install prefix /usr, decided
# when installing: `cmake --install --prefix` may change it) or when asked with
# FREPKIT_INSTALL_DEBIAN_PARAVIEW_LINKS: link both where Debian's ParaView finds plug-ins by name,
# and write bin/paraview.conf. The ParaView GUI (5.11) reads the plugins XMLs listed in <its
# bin>/paraview.conf; Debian's package ships none, so neither its own paraview.plugins.xml nor
# ours would be read. This one lists both: in /usr the GUI then auto-loads FRepKit. Under any
# other prefix they would only clutter it (no ParaView there reads them).
option(FREPKIT_INSTALL_DEBIAN_PARAVIEW_LINKS
  "Install the links for Debian's ParaView and bin/paraview.conf under any prefix (always in /usr)"
  OFF)
if(TARGET FRepKit AND FREPKIT_PARAVIEW_PLUGIN_LINK_DIR)
  file(RELATIVE_PATH _frepkit_plugin_link_target
    "/prefix/${FREPKIT_PARAVIEW_PLUGIN_LINK_DIR}" "/prefix/${FREPKIT_INSTALL_PLUGIN_DIR}")
  file(WRITE "${PROJECT_BINARY_DIR}/CMakeFiles/paraview.conf"
    "../${FREPKIT_PARAVIEW_PLUGIN_LINK_DIR}/paraview.plugins.xml\n"
    "../${FREPKIT_PARAVIEW_PLUGIN_LINK_DIR}/frepkit.plugins.xml\n")
  install(CODE "
    if(\"\${CMAKE_INSTALL_PREFIX}\" STREQUAL \"/usr\" OR ${FREPKIT_INSTALL_DEBIAN_PARAVIEW_LINKS})
      set(_dir \"\$ENV{DESTDIR}\${CMAKE_INSTALL_PREFIX}/${FREPKIT_PARAVIEW_PLUGIN_LINK_DIR}\")
      file(MAKE_DIRECTORY \"\${_dir}\")
      foreach(_name IN ITEMS FRepKit frepkit.plugins.xml)
        message(STATUS \"Installing: \${_dir}/\${_name} -> ${_frepkit_plugin_link_target}/\${_name}\")
        file(CREATE_LINK \"${_frepkit_plugin_link_target}/\${_name}\" \"\${_dir}/\${_name}\" SYMBOLIC)
      endforeach()
      file(INSTALL DESTINATION \"\${CMAKE_INSTALL_PREFIX}/bin\" TYPE FILE
        FILES \"${PROJECT_BINARY_DIR}/CMakeFiles/paraview.conf\")
    endif()")
  unset(_frepkit_plugin_link_target)
endif()

# --- The CMake package -------------------------------------------------------------------------
# One export set, FRepKitTargets: the plain libraries (frepkit_add_library) and the VTK modules
# (vtk_module_build INSTALL_EXPORT, which also writes FRepKit-targets.cmake and the module
# properties). Without VTK the set is installed here.
if(NOT FREPKIT_ENABLE_VTK)
  install(EXPORT FRepKitTargets NAMESPACE FRepKit:: FILE FRepKit-targets.cmake
    DESTINATION "${FREPKIT_INSTALL_CMAKE_DIR}")
  export(EXPORT FRepKitTargets NAMESPACE FRepKit::
    FILE "${PROJECT_BINARY_DIR}/${FREPKIT_INSTALL_CMAKE_DIR}/FRepKit-targets.cmake")
endif()

# The VTK components the modules' interfaces need (their DEPENDS), for find_dependency(VTK).
set(FREPKIT_CONFIG_VTK_COMPONENTS)
foreach(_frepkit_module IN LISTS FREPKIT_VTK_MODULES)
  get_property(_depends GLOBAL PROPERTY "_vtk_module_${_frepkit_module}_depends")
  foreach(_depend IN LISTS _depends)
    if(_depend MATCHES "^VTK::(.*)$")
      list(APPEND FREPKIT_CONFIG_VTK_COMPONENTS "${CMAKE_MATCH_1}")
    endif()
  endforeach()
endforeach()
list(REMOVE_DUPLICATES FREPKIT_CONFIG_VTK_COMPONENTS)
list(JOIN FREPKIT_CONFIG_VTK_COMPONENTS " " FREPKIT_CONFIG_VTK_COMPONENTS)

configure_package_config_file(cmake/FRepKitConfig.cmake.in
  "${PROJECT_BINARY_DIR}/CMakeFiles/FRepKitConfig.cmake"
  INSTALL_DESTINATION "${FREPKIT_INSTALL_CMAKE_DIR}")
write_basic_package_version_file("${PROJECT_BINARY_DIR}/CMakeFiles/FRepKitConfigVersion.cmake"
  VERSION "${PROJECT_VERSION}" COMPATIBILITY SameMinorVersion)
install(FILES
  "${PROJECT_BINARY_DIR}/CMakeFiles/FRepKitConfig.cmake"
  "${PROJECT_BINARY_DIR}/CMakeFiles/FRepKitConfigVersion.cmake"
  DESTINATION "${FREPKIT_INSTALL_CMAKE_DIR}")

# The public headers, for the installation test: "<base dir>|<header>" per plain library header,
# "module|<header>" per VTK module header. Everything else under include/frepkit is a leak.
set(_frepkit_header_list "")
get_property(_frepkit_plain GLOBAL PROPERTY FREPKIT_PLAIN_LIBRARIES)
foreach(_target IN LISTS _frepkit_plain)
  string(APPEND _frepkit_header_list
    "$<TARGET_PROPERTY:${_target},HEADER_DIRS>|$<JOIN:$<TARGET_PROPERTY:${_target},HEADER_SET>,\n$<TARGET_PROPERTY:${_target},HEADER_DIRS>|>\n")
endforeach()
foreach(_frepkit_module IN LISTS FREPKIT_VTK_MODULES)
  vtk_module_get_property("${_frepkit_module}" PROPERTY "INTERFACE_vtk_module_headers"
    VARIABLE _headers)
  foreach(_header IN LISTS _headers)
    string(APPEND _frepkit_header_list "module|${_header}\n")
  endforeach()
endforeach()
file(GENERATE OUTPUT "${PROJECT_BINARY_DIR}/public-headers.txt" CONTENT "${_frepkit_header_list}")
unset(_frepkit_header_list)
unset(_frepkit_plain)

# --- The Debian package: cpack -G DEB in the build folder -> frepkit_<version>_amd64.deb -------
set(CPACK_PACKAGE_NAME frepkit)
set(CPACK_PACKAGE_VENDOR "FRepKit")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "function-representation (HyperFun) modelling in n dimensions for VTK and ParaView")
set(CPACK_PACKAGE_DESCRIPTION
  "The frepkit command-line tool, the FRepStudio application, the ParaView plug-in, the FRepKit\nlibraries and VTK modules with their headers and CMake package, examples and documentation.")
set(CPACK_PACKAGE_CONTACT "FRepKit developers <frepkit@localhost>")
# Into /usr, so the plug-in links land where Debian's ParaView looks; DESTDIR staging keeps
# CMAKE_INSTALL_PREFIX = /usr while the package is made.
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_SET_DESTDIR ON)
set(CPACK_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://localhost/frepkit")
# The shared-library dependencies (libvtk*-pv5.11 -> paraview, Qt5, OpenImageIO, libsndfile,
# FreeType, ...) come from dpkg-shlibdeps (dpkg-dev); the programs and data used at run time
# that no library links are listed by hand.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS_PRIVATE_DIRS "${PROJECT_BINARY_DIR}/lib")
set(CPACK_DEBIAN_PACKAGE_DEPENDS "paraview, python3-paraview, ffmpeg, fonts-dejavu-core")
set(CPACK_GENERATOR DEB)
set(CPACK_SOURCE_GENERATOR "")
include(CPack)
