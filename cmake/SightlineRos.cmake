# ROS 1 (Debian 12's roscpp 1.15 / rosbag 1.15 packages): rosbag files as a source, live topics,
# and the sightline-node front end. ON by default; configure fails loudly when ON and missing.
#
# Two interface targets keep ROS's include paths and libraries in the few modules that use them:
#   sightline_ros_bag  - rosbag + the message headers (reading and writing .bag files, no master);
#   sightline_ros_live - roscpp + tf2_ros + the message headers (topics, a master, tf).
#
# Trap: rosbag's CMake config pulls Debian's pluginlib, which loads ament_cmake_core, which runs
# Python's ament_package; with a python3 on PATH that is not Debian's, configure fails. Both
# Python3_EXECUTABLE and PYTHON_EXECUTABLE must name /usr/bin/python3 before the find_package.
option(SIGHTLINE_WITH_ROS "Build the ROS 1 integration (rosbag source, live topics, sightline-node)" ON)
set(SIGHTLINE_ROS_STATUS "NO (disabled)")
if(NOT SIGHTLINE_WITH_ROS)
  return()
endif()

if(EXISTS /usr/bin/python3)
  set(Python3_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python for ROS's CMake configs")
  set(PYTHON_EXECUTABLE /usr/bin/python3 CACHE FILEPATH "Python for ROS's CMake configs")
endif()
set(_sightline_ros_packages roscpp rosbag tf2_ros sensor_msgs nav_msgs geometry_msgs tf2_msgs
  visualization_msgs diagnostic_msgs std_msgs std_srvs)
set(_sightline_ros_missing)
foreach(package IN LISTS _sightline_ros_packages)
  find_package(${package} QUIET)
  if(NOT ${package}_FOUND)
    list(APPEND _sightline_ros_missing ${package})
  endif()
endforeach()
if(_sightline_ros_missing)
  message(FATAL_ERROR "SIGHTLINE_WITH_ROS is ON but these ROS 1 packages were not found: "
    "${_sightline_ros_missing}. Install them with packaging/install-deps.sh (libroscpp-dev "
    "librosbag-dev libsensor-msgs-dev ... ros-core) or configure with -DSIGHTLINE_WITH_ROS=OFF.")
endif()

set(_sightline_ros_msg_includes)
foreach(package IN ITEMS sensor_msgs nav_msgs geometry_msgs tf2_msgs visualization_msgs
        diagnostic_msgs std_msgs std_srvs)
  list(APPEND _sightline_ros_msg_includes ${${package}_INCLUDE_DIRS})
endforeach()

add_library(sightline_ros_bag INTERFACE)
target_include_directories(sightline_ros_bag SYSTEM INTERFACE
  ${rosbag_INCLUDE_DIRS} ${roscpp_INCLUDE_DIRS} ${_sightline_ros_msg_includes})
target_link_libraries(sightline_ros_bag INTERFACE ${rosbag_LIBRARIES} ${roscpp_LIBRARIES})

add_library(sightline_ros_live INTERFACE)
target_include_directories(sightline_ros_live SYSTEM INTERFACE
  ${roscpp_INCLUDE_DIRS} ${tf2_ros_INCLUDE_DIRS} ${_sightline_ros_msg_includes})
target_link_libraries(sightline_ros_live INTERFACE ${roscpp_LIBRARIES} ${tf2_ros_LIBRARIES})

# roscore/rosmaster for the tests that start their own master.
find_program(SIGHTLINE_ROSCORE roscore)
set(SIGHTLINE_ROS_STATUS "YES (roscpp ${roscpp_VERSION}, rosbag ${rosbag_VERSION}; roscore: ${SIGHTLINE_ROSCORE})")
