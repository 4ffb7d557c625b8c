# Every dependency Sightline uses, as imported targets, from Debian 12's packages.
#
# The Qt5 trap: Debian builds VTK's Qt module, OpenCV's highgui and PCL's CMake config against Qt5.
# Sightline is a Qt6 program, so no Qt5 library may be linked or loaded. Hence:
#  - VTK components are listed explicitly and none of them is a Qt module;
#  - OpenCV components are listed explicitly (never highgui);
#  - the VTK Qt targets that PCL puts on its link interfaces are removed right after find_package.

find_package(Threads REQUIRED)
find_package(Eigen3 3.3 REQUIRED NO_MODULE)
find_package(yaml-cpp REQUIRED)
find_package(Ceres REQUIRED)
find_package(OpenCV 4 REQUIRED COMPONENTS
  core imgproc imgcodecs features2d calib3d video flann videoio objdetect rgbd)

find_package(Qt6 6.4 REQUIRED COMPONENTS
  Core Gui Widgets OpenGL OpenGLWidgets Concurrent Network Test LinguistTools)

set(SIGHTLINE_VTK_COMPONENTS
  CommonCore CommonDataModel CommonColor CommonTransforms FiltersSources FiltersGeneral
  RenderingCore RenderingOpenGL2 RenderingUI InteractionStyle RenderingFreeType
  RenderingAnnotation)
find_package(VTK 9.1 REQUIRED COMPONENTS ${SIGHTLINE_VTK_COMPONENTS})
# PCL overwrites VTK_LIBRARIES; keep our own list.
set(SIGHTLINE_VTK_TARGETS)
foreach(component IN LISTS SIGHTLINE_VTK_COMPONENTS)
  list(APPEND SIGHTLINE_VTK_TARGETS VTK::${component})
endforeach()

find_package(PCL 1.12 REQUIRED COMPONENTS common io kdtree search features filters segmentation
  sample_consensus surface)
set(_sightline_vtk_qt_targets VTK::GUISupportQt VTK::RenderingQt VTK::ViewsQt)
foreach(pcl_target IN ITEMS pcl_common pcl_io pcl_io_ply pcl_kdtree pcl_search pcl_features
        pcl_filters pcl_segmentation pcl_sample_consensus pcl_surface pcl_2d pcl_octree pcl_ml)
  if(TARGET ${pcl_target})
    get_target_property(_links ${pcl_target} INTERFACE_LINK_LIBRARIES)
    if(_links)
      list(REMOVE_ITEM _links ${_sightline_vtk_qt_targets})
      set_target_properties(${pcl_target} PROPERTIES INTERFACE_LINK_LIBRARIES "${_links}")
    endif()
  endif()
endforeach()
list(REMOVE_ITEM PCL_LIBRARIES ${_sightline_vtk_qt_targets})
# PCL's config also adds every VTK library it was built with; Sightline links only what it uses.
add_library(sightline_pcl INTERFACE)
target_include_directories(sightline_pcl SYSTEM INTERFACE ${PCL_INCLUDE_DIRS})
target_compile_definitions(sightline_pcl INTERFACE ${PCL_DEFINITIONS})
target_link_libraries(sightline_pcl INTERFACE ${PCL_LIBRARIES})

if(SIGHTLINE_BUILD_TESTS)
  find_package(GTest REQUIRED)
endif()
if(SIGHTLINE_BUILD_BENCHMARKS)
  find_package(benchmark REQUIRED)
endif()

# Optional sensors: ON by default, and configure fails loudly when ON and missing.
find_package(PkgConfig REQUIRED)
set(SIGHTLINE_OPENNI2_STATUS "NO (disabled)")
if(SIGHTLINE_WITH_OPENNI2)
  pkg_check_modules(OPENNI2 IMPORTED_TARGET libopenni2)
  if(NOT OPENNI2_FOUND)
    message(FATAL_ERROR "SIGHTLINE_WITH_OPENNI2 is ON but OpenNI2 was not found. "
      "Install libopenni2-dev (packaging/install-deps.sh) or configure with -DSIGHTLINE_WITH_OPENNI2=OFF.")
  endif()
  set(SIGHTLINE_OPENNI2_STATUS "YES (${OPENNI2_VERSION})")
endif()
set(SIGHTLINE_ARAVIS_STATUS "NO (disabled)")
if(SIGHTLINE_WITH_ARAVIS)
  pkg_check_modules(ARAVIS IMPORTED_TARGET aravis-0.8)
  if(NOT ARAVIS_FOUND)
    message(FATAL_ERROR "SIGHTLINE_WITH_ARAVIS is ON but Aravis 0.8 was not found. "
      "Install libaravis-dev (packaging/install-deps.sh) or configure with -DSIGHTLINE_WITH_ARAVIS=OFF.")
  endif()
  set(SIGHTLINE_ARAVIS_STATUS "YES (${ARAVIS_VERSION})")
endif()

include(SightlineRos)
