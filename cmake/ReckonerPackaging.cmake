# What `cmake --install` puts where, the man pages, and the Debian package of `cpack -G DEB`
# (docs/packaging.md). The programs' own install() rules are in app/CMakeLists.txt, the desktop entry's
# and the icon's in resources/CMakeLists.txt; GNUInstallDirs is included by the top CMakeLists.txt.
#
# Everything the programs read at run time is either compiled in (scenarios, portrayal tables and the
# chart RK5SOUND: resources/embedded.h) or another Debian package's file (GDAL's S-57 catalogue from
# gdal-data, GSHHG's shorelines from gmt-gshhg-low, Qt's platform plugins): the installed programs need
# neither the source nor the build tree.

# The documentation: the README and docs/*.md, flat in share/doc/reckoner as in the source tree's docs/.
# Named here rather than CMAKE_INSTALL_DOCDIR, which is share/doc/Reckoner (PROJECT_NAME) and, once
# Qt's packages have included GNUInstallDirs, already in the cache: Debian wants the package's name.
set(RECKONER_INSTALL_DOCDIR ${CMAKE_INSTALL_DATAROOTDIR}/doc/reckoner)
file(GLOB reckoner_docs CONFIGURE_DEPENDS ${PROJECT_SOURCE_DIR}/docs/*.md)
install(FILES ${PROJECT_SOURCE_DIR}/README.md ${reckoner_docs} DESTINATION ${RECKONER_INSTALL_DOCDIR})

# Man pages generated from the programs' own --help and --version by help2man (Debian's help2man; the
# bootstrap installs it), with the hand-written sections of resources/package/*.h2m. reckoner-cli's
# page also carries every command's --help (cmake/CliCommandsHelp.cmake). Compressed as Debian policy
# wants them. Without help2man the build goes on without man pages.
find_program(RECKONER_HELP2MAN help2man)
find_program(RECKONER_GZIP gzip)
if(RECKONER_HELP2MAN AND RECKONER_GZIP)
  set(man_dir ${PROJECT_BINARY_DIR}/man)
  set(package_dir ${PROJECT_SOURCE_DIR}/resources/package)
  # help2man runs the program by the name given; on PATH, so that usage lines say "reckoner", not the
  # build path. No display is needed: both programs answer --help and --version without one.
  set(run_env ${CMAKE_COMMAND} -E env "PATH=$<TARGET_FILE_DIR:reckoner>:$ENV{PATH}" QT_QPA_PLATFORM=offscreen)
  add_custom_command(
    OUTPUT ${man_dir}/reckoner-cli.1.gz
    COMMAND ${CMAKE_COMMAND} -E make_directory ${man_dir}
    COMMAND ${CMAKE_COMMAND} -DCLI=$<TARGET_FILE:reckoner-cli> -DOUTPUT=${man_dir}/reckoner-cli-commands.h2m
            -P ${PROJECT_SOURCE_DIR}/cmake/CliCommandsHelp.cmake
    COMMAND ${run_env} ${RECKONER_HELP2MAN} --no-info --section=1
            "--name=headless runs of the Reckoner dead-reckoning and target-tracking engine"
            --include=${package_dir}/reckoner-cli.h2m --include=${man_dir}/reckoner-cli-commands.h2m
            --output=${man_dir}/reckoner-cli.1 reckoner-cli
    COMMAND ${RECKONER_GZIP} -9nf ${man_dir}/reckoner-cli.1
    DEPENDS reckoner-cli ${package_dir}/reckoner-cli.h2m ${PROJECT_SOURCE_DIR}/cmake/CliCommandsHelp.cmake
    COMMENT "Man page of reckoner-cli (help2man)"
    VERBATIM)
  add_custom_command(
    OUTPUT ${man_dir}/reckoner.1.gz
    COMMAND ${CMAKE_COMMAND} -E make_directory ${man_dir}
    COMMAND ${run_env} ${RECKONER_HELP2MAN} --no-info --section=1
            "--name=dead-reckoning and target-tracking ECDIS (the chart window)"
            --include=${package_dir}/reckoner.h2m --output=${man_dir}/reckoner.1 reckoner
    COMMAND ${RECKONER_GZIP} -9nf ${man_dir}/reckoner.1
    DEPENDS reckoner ${package_dir}/reckoner.h2m
    COMMENT "Man page of reckoner (help2man)"
    VERBATIM)
  add_custom_target(reckoner_man ALL DEPENDS ${man_dir}/reckoner-cli.1.gz ${man_dir}/reckoner.1.gz)
  install(FILES ${man_dir}/reckoner-cli.1.gz ${man_dir}/reckoner.1.gz DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
  set(RECKONER_MAN_PAGES ON)
else()
  message(WARNING "help2man (or gzip) not found: no man pages (scripts/bootstrap.sh deps installs help2man)")
  set(RECKONER_MAN_PAGES OFF)
endif()

# The Debian package. The version is the build's (cmake/WriteVersion.cmake), read by cpack when it runs
# (cmake/ReckonerPackagingVersion.cmake), so a package built after a new commit carries that commit's
# version without reconfiguring.
set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME reckoner)
set(CPACK_PACKAGE_VENDOR "Reckoner")
set(CPACK_PACKAGE_CONTACT "Reckoner maintainers <maintainers@users.noreply.h-seed-f53b6da7.example>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "dead-reckoning and target-tracking ECDIS")
# The extended description, in lines under 80 columns as Debian wants them (CPack indents them).
string(JOIN "\n" CPACK_PACKAGE_DESCRIPTION
  "An ECDIS-style workbench: own ship's 11-state dead-reckoning Kalman filter"
  "(GPS, Loran-C, speed log, gyro), radar target tracking (ARPA) with CPA/TCPA,"
  "AIS, S-57 charts drawn with its own portrayal, routes with anti-grounding"
  "checks, alerts and a voyage recorder."
  "The chart window is reckoner; reckoner-cli runs the same engine headless:"
  "scenarios, Monte Carlo studies, replay of recorded NMEA 0183 and radar data,"
  "live NMEA connections. It carries its own fictional harbour chart and"
  "scenarios. Not for navigation.")
set(CPACK_PACKAGE_INSTALL_DIRECTORY reckoner)
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # reckoner_<version>_<arch>.deb
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_COMPRESSION_TYPE xz)
# The shared libraries' packages come from dpkg-shlibdeps (libqt6*, libgdal32, libgeographiclib,
# libsqlite3, libpugixml, ...). What it cannot see because the programs load it at run time is named:
# Qt's platform plugins (xcb for the window, offscreen for `reckoner-cli chart render`); GDAL's S-57
# catalogue comes with libgdal32's own dependency gdal-data. GSHHG's shorelines only draw the world
# background around the charts (the window says when they are missing): recommended.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins")
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "gmt-gshhg-low")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_PROJECT_CONFIG_FILE ${PROJECT_SOURCE_DIR}/cmake/ReckonerPackagingVersion.cmake)
set(RECKONER_VERSION_FILE ${RECKONER_GENERATED_DIR}/reckoner_version.cmake)
set(CPACK_RECKONER_VERSION_FILE ${RECKONER_VERSION_FILE})  # CPACK_* variables reach CPackConfig.cmake
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})  # replaced by the build's version when cpack runs
include(CPack)
