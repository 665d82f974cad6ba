# The visualisation stack, found now so that it is proven from day one (see DESIGN.md):
# ParaView 5.11 and the VTK it bundles (never the system libvtk9-dev), Qt5, OpenImageIO,
# libsndfile. A bare find_package(ParaView) needs ~59 more packages: ask for two components.
find_package(ParaView 5.11 REQUIRED COMPONENTS RemotingCore RemotingServerManager)
find_package(VTK REQUIRED COMPONENTS
  CommonCore CommonDataModel CommonExecutionModel FiltersCore FiltersGeneral
  ImagingHybrid IOImage IOGeometry RenderingCore RenderingOpenGL2 GUISupportQt)
find_package(Qt5 5.15 REQUIRED COMPONENTS Widgets)
find_package(OpenImageIO REQUIRED)
find_package(PkgConfig REQUIRED)
pkg_check_modules(SNDFILE REQUIRED IMPORTED_TARGET sndfile)

message(STATUS "FRepKit: ParaView ${ParaView_VERSION}, VTK ${VTK_VERSION} (${VTK_DIR}), "
  "Qt ${Qt5_VERSION}, OpenImageIO ${OpenImageIO_VERSION}")
