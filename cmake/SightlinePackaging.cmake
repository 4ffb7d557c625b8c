# What `cmake --install` and the Debian package hold: the programs (sightline-node too when
# built with ROS), their man pages (generated from --help at build time), the desktop entry,
# the icon, the AppStream metainfo, the translations and the README. No test, benchmark or
# static library is installed.
# packaging/make-deb.sh builds the package from an existing build folder with CPack.
include(GNUInstallDirs)

# `install` and CPack must not rebuild the whole tree (tests, benchmarks): make-deb.sh builds
# exactly the installed targets first.
set(CMAKE_SKIP_INSTALL_ALL_DEPENDENCY ON)

# sightline-node (the ROS 1 front end) when the build has ROS.
set(_programs sightline sightline-cli)
if(TARGET sightline-node)
  list(APPEND _programs sightline-node)
endif()
install(TARGETS ${_programs} RUNTIME DESTINATION ${CMAKE_INSTALL_BINDIR})
# sightline-cli hands `run stereo-vo` on a recorded stereo dataset to sightline-cli-stereo and
# every other command but --help, --version and `info` of a dataset to the full program; it
# finds both at ../libexec/sightline/ from its own folder (app/cli/CMakeLists.txt).
install(TARGETS sightline-cli-full sightline-cli-stereo
        RUNTIME DESTINATION ${CMAKE_INSTALL_LIBEXECDIR}/sightline)

# Man pages from each program's --help, so they never drift from it (sightline-cli-full prints
# the same as sightline-cli and has no page of its own).
set(_man_dir ${CMAKE_BINARY_DIR}/man)
set(_man_pages)
foreach(_program IN LISTS _programs)
  if(_program STREQUAL "sightline")
    set(_summary "robot perception on live sensors and recorded data (desktop application)")
  elseif(_program STREQUAL "sightline-node")
    set(_summary "run one Sightline pipeline as a ROS 1 node and publish its results")
  else()
    set(_summary "run Sightline's perception pipelines, evaluations and recordings headless")
  endif()
  add_custom_command(
    OUTPUT ${_man_dir}/${_program}.1.gz
    COMMAND ${CMAKE_COMMAND} -E make_directory ${_man_dir}
    COMMAND bash ${PROJECT_SOURCE_DIR}/packaging/help-to-man.sh $<TARGET_FILE:${_program}>
            ${_program} ${_summary} ${PROJECT_VERSION} ${_man_dir}/${_program}.1
    COMMAND gzip -9nf ${_man_dir}/${_program}.1
    DEPENDS ${_program} ${PROJECT_SOURCE_DIR}/packaging/help-to-man.sh
    COMMENT "Man page of ${_program} from its --help"
    VERBATIM)
  list(APPEND _man_pages ${_man_dir}/${_program}.1.gz)
endforeach()
add_custom_target(sightline_man_pages ALL DEPENDS ${_man_pages})
install(FILES ${_man_pages} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)

install(FILES ${PROJECT_SOURCE_DIR}/resources/sightline.desktop
        DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
install(FILES ${PROJECT_SOURCE_DIR}/resources/sightline.svg
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
install(FILES ${PROJECT_SOURCE_DIR}/resources/sightline.png
        DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/256x256/apps)
install(FILES ${PROJECT_SOURCE_DIR}/resources/org.sightline.Sightline.metainfo.xml
        DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
install(FILES ${PROJECT_SOURCE_DIR}/README.md DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/sightline)

# The translations are compiled into sightline (:/i18n); the .qm files are installed beside it
# as well, for translators checking what the package ships.
file(GLOB _ts_files ${PROJECT_SOURCE_DIR}/translations/sightline_*.ts)
foreach(_ts IN LISTS _ts_files)
  get_filename_component(_base ${_ts} NAME_WE)
  install(FILES ${CMAKE_BINARY_DIR}/app/sightline/${_base}.qm
          DESTINATION ${CMAKE_INSTALL_DATADIR}/sightline/translations)
endforeach()

# The Debian package: sightline_VERSION_ARCH.deb, its library dependencies computed by
# dpkg-shlibdeps from the installed programs, plus what Qt and VTK load at run time (the platform
# plugins, Mesa's OpenGL drivers), which no linker sees.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME sightline)
set(CPACK_PACKAGE_VENDOR "Sightline")
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "robot perception on live sensors and recorded data")
set(CPACK_PACKAGE_DESCRIPTION
    "Sightline runs robot perception pipelines (indoor mapping, stereo visual odometry, a\n"
    "mobility map, monocular SLAM, a button picker for a wheelchair-mounted arm) on RGB-D,\n"
    "stereo and monocular cameras, live or recorded. sightline is the desktop application,\n"
    "sightline-cli runs every pipeline and evaluation headless, sightline-node runs them as\n"
    "a ROS 1 node.")
string(JOIN "" CPACK_PACKAGE_DESCRIPTION ${CPACK_PACKAGE_DESCRIPTION})
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "Sightline developers <sightline@localhost>")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins, libgl1-mesa-dri")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "qt6-translations-l10n")
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS OFF)
set(CPACK_OUTPUT_FILE_PREFIX ${CMAKE_BINARY_DIR}/packages)
include(CPack)
