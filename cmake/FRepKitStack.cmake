# The visualisation stack, found now so that it is proven from day one (see DESIGN.md):
# ParaView 5.11 and the VTK it bundles (never the system libvtk9-dev), Qt5, OpenImageIO,
# libsndfile. A bare find_package(ParaView) needs ~59 more packages: ask for two components.
#
# A missing or wrong ParaView/VTK stops here with one message that names the Debian package.
set(_frepkit_stack_hint "On Debian 12 install it with: apt-get install paraview-dev \
python3-paraview (or run Scripts/install-dependencies.sh, which installs every package FRepKit \
needs), or point -DParaView_DIR= at the folder with ParaViewConfig.cmake of a ParaView 5.11. \
Do not use libvtk9-dev: FRepKit builds against the VTK that ParaView bundles.")
find_package(ParaView 5.11 QUIET COMPONENTS RemotingCore RemotingServerManager)
if(NOT ParaView_FOUND)
  set(_frepkit_reason "")
  if(ParaView_CONSIDERED_VERSIONS)
    string(APPEND _frepkit_reason " Found ParaView ${ParaView_CONSIDERED_VERSIONS} "
      "(${ParaView_CONSIDERED_CONFIGS}), which is not 5.11.")
  elseif(ParaView_NOT_FOUND_MESSAGE)
    string(APPEND _frepkit_reason " ${ParaView_NOT_FOUND_MESSAGE}")
  elseif(ParaView_DIR)
    string(APPEND _frepkit_reason " ParaView_DIR=${ParaView_DIR} holds no ParaViewConfig.cmake.")
  endif()
  message(FATAL_ERROR "FRepKit needs ParaView 5.11 (its CMake package, with the VTK 9.2 it "
    "bundles): not found.${_frepkit_reason} ${_frepkit_stack_hint}")
endif()
find_package(VTK QUIET COMPONENTS
  CommonCore CommonDataModel CommonExecutionModel FiltersCore FiltersGeneral
  ImagingHybrid IOImage IOGeometry RenderingCore RenderingOpenGL2 GUISupportQt)
if(NOT VTK_FOUND OR NOT VTK_DIR MATCHES "paraview-5\\.11")
  message(FATAL_ERROR "FRepKit needs the VTK bundled with ParaView 5.11 "
    "(cmake/paraview-5.11/vtk), found: ${VTK_DIR}. ${VTK_NOT_FOUND_MESSAGE} "
    "${_frepkit_stack_hint}")
endif()
unset(_frepkit_stack_hint)
find_package(Qt5 5.15 REQUIRED COMPONENTS Widgets)
find_package(OpenImageIO REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(SNDFILE REQUIRED IMPORTED_TARGET sndfile)

message(STATUS "FRepKit: ParaView ${ParaView_VERSION}, VTK ${VTK_VERSION} (${VTK_DIR}), "
  "Qt ${Qt5_VERSION}, OpenImageIO ${OpenImageIO_VERSION}")
