# sightline_core_library(NAME SOURCES ... DEPS ...)
# A Qt-free core module. Configure fails if any of its link dependencies is a Qt target.
function(sightline_core_library name)
  cmake_parse_arguments(ARG "" "" "SOURCES;DEPS;PRIVATE_DEPS" ${ARGN})
  foreach(dep IN LISTS ARG_DEPS ARG_PRIVATE_DEPS)
    if(dep MATCHES "^Qt[56]?::" OR dep MATCHES "^VTK::")
      message(FATAL_ERROR "core module ${name} must not link ${dep}: core/ is Qt-free")
    endif()
  endforeach()
  add_library(${name} STATIC ${ARG_SOURCES})
  target_include_directories(${name} PUBLIC ${PROJECT_SOURCE_DIR})
  target_link_libraries(${name} PUBLIC ${ARG_DEPS} PRIVATE ${ARG_PRIVATE_DEPS})
  target_compile_options(${name} PRIVATE -Wall -Wextra -Wno-unused-parameter)
  set_property(GLOBAL APPEND PROPERTY SIGHTLINE_CORE_TARGETS ${name})
endfunction()

# sightline_add_gtest(MODULE NAME SOURCES ... DEPS ... [ARGS ...] [LABELS ...] [RUN_SERIAL])
# One gtest executable per source module; ctest names read "module/Suite.Test". RUN_SERIAL: its
# tests run alone under ctest -j.
function(sightline_add_gtest module name)
  cmake_parse_arguments(ARG "RUN_SERIAL" "" "SOURCES;DEPS;LABELS;ENVIRONMENT" ${ARGN})
  set(target test_${name})
  add_executable(${target} ${ARG_SOURCES})
  target_link_libraries(${target} PRIVATE ${ARG_DEPS} GTest::gtest GTest::gtest_main GTest::gmock
                        sightline_test_support)
  set(props)
  if(ARG_ENVIRONMENT OR ARG_RUN_SERIAL)
    set(props PROPERTIES)
  endif()
  if(ARG_ENVIRONMENT)
    list(APPEND props ENVIRONMENT "${ARG_ENVIRONMENT}")
  endif()
  if(ARG_RUN_SERIAL)
    list(APPEND props RUN_SERIAL TRUE)
  endif()
  gtest_discover_tests(${target} TEST_PREFIX "${module}/" DISCOVERY_TIMEOUT 60 ${props})
endfunction()

# sightline_version_header(): the target sightline_version, whose generated header
# "sightline_version.h" defines SIGHTLINE_VERSION and SIGHTLINE_GIT_COMMIT for --version.
function(sightline_version_header)
  set(dir ${CMAKE_BINARY_DIR}/generated)
  add_custom_target(sightline_version_header
    COMMAND ${CMAKE_COMMAND} -DSOURCE_DIR=${PROJECT_SOURCE_DIR} -DOUTPUT=${dir}/sightline_version.h
            -DVERSION=${PROJECT_VERSION} -P ${PROJECT_SOURCE_DIR}/cmake/SightlineVersionHeader.cmake
    BYPRODUCTS ${dir}/sightline_version.h
    COMMENT "Version header (git commit)")
  add_library(sightline_version INTERFACE)
  target_include_directories(sightline_version INTERFACE ${dir})
  add_dependencies(sightline_version sightline_version_header)
endfunction()
