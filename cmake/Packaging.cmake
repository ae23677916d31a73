# Packaging (docs/install.md): the man page, the Debian package built by `cpack -G DEB`
# (tools/package.sh), and what a .deb needs beside the install rules of CMakeLists.txt.
# Included at the end of CMakeLists.txt, after every target is defined.

# ---------------------------------------------------------------- the library's ABI version
# libmassprops.so.0.1 (SONAME) -> .so.0.1.0; libmassprops.so stays the link name. Until 1.0 each
# minor version may change the ABI, so the SONAME carries MAJOR.MINOR.
if(BUILD_SHARED_LIBS)
  set_target_properties(massprops PROPERTIES VERSION ${PROJECT_VERSION}
                        SOVERSION ${PROJECT_VERSION_MAJOR}.${PROJECT_VERSION_MINOR})
endif()

# ---------------------------------------------------------------- the man page
# massprops.1 is written at build time by help2man (Debian: help2man) from the tool's own --help
# and --version, with a COMMANDS section holding each subcommand's --help (cmake/man_page.cmake).
find_program(MASSPROPS_HELP2MAN help2man DOC "help2man (Debian: help2man), writes massprops.1")
if(MASSPROPS_HELP2MAN AND NOT CMAKE_CROSSCOMPILING)
  set(man_page "${PROJECT_BINARY_DIR}/man/massprops.1")
  add_custom_command(OUTPUT "${man_page}" "${man_page}.gz"
    COMMAND ${CMAKE_COMMAND} -DTOOL=$<TARGET_FILE:massprops-cli> -DHELP2MAN=${MASSPROPS_HELP2MAN}
            -DOUTPUT=${man_page} -P "${PROJECT_SOURCE_DIR}/cmake/man_page.cmake"
    DEPENDS massprops-cli "${PROJECT_SOURCE_DIR}/cmake/man_page.cmake"
    COMMENT "Writing the man page massprops.1 with help2man" VERBATIM)
  add_custom_target(massprops-man ALL DEPENDS "${man_page}")
  install(FILES "${man_page}.gz" DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
else()
  message(STATUS "help2man not found: no man page (Debian: help2man)")
endif()

# ---------------------------------------------------------------- Debian package
# MASSPROPS_DEBIAN_PACKAGE=ON (tools/package.sh) adds what Debian's policy asks of a package beside
# the program: /usr/share/doc/massprops/copyright and changelog.gz. A .deb installs into /usr.
option(MASSPROPS_DEBIAN_PACKAGE "Install the files a Debian package needs (tools/package.sh)" OFF)
set(MASSPROPS_DEB_MAINTAINER
    "Seed 44f16922 maintainers <maintainers@users.noreply.h-seed-44f16922.example>"
    CACHE STRING "The Maintainer field of the .deb and of its changelog")
if(MASSPROPS_DEBIAN_PACKAGE)
  if(NOT CMAKE_INSTALL_PREFIX STREQUAL "/usr")
    message(FATAL_ERROR "MASSPROPS_DEBIAN_PACKAGE needs -DCMAKE_INSTALL_PREFIX=/usr, "
                        "got ${CMAKE_INSTALL_PREFIX}")
  endif()
  # The changelog's date: SOURCE_DATE_EPOCH when set (reproducible builds), else now.
  string(TIMESTAMP MASSPROPS_DEB_DATE "%a, %d %b %Y %H:%M:%S +0000" UTC)
  set(deb_doc "${PROJECT_BINARY_DIR}/debian-doc")
  configure_file(cmake/debian/changelog.in "${deb_doc}/changelog" @ONLY)
  configure_file(cmake/debian/copyright "${deb_doc}/copyright" COPYONLY)
  add_custom_command(OUTPUT "${deb_doc}/changelog.gz"
    COMMAND gzip -9 -n -f -k "${deb_doc}/changelog"
    DEPENDS "${deb_doc}/changelog" VERBATIM)
  add_custom_target(massprops-debian-doc ALL DEPENDS "${deb_doc}/changelog.gz")
  install(FILES "${deb_doc}/changelog.gz" "${deb_doc}/copyright"
          DESTINATION ${CMAKE_INSTALL_DATADIR}/doc/massprops)
endif()

set(CPACK_PACKAGE_NAME massprops)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_VENDOR "massprops")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "validate and repair robot mass properties (URDF, SDF)")
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # massprops_VERSION_ARCH.deb
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${MASSPROPS_DEB_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
# The Description's long part; cpack puts CPACK_PACKAGE_DESCRIPTION_SUMMARY before it as the first
# line and indents the rest as deb-control(5) asks (an empty line becomes " .").
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "massprops checks that the mass, center of mass and
rotational inertia of each link of a URDF or SDF robot model could belong to
a real body, finds the defects CAD exports have (wrong units, inertia about
the wrong point, forgotten masses), rewrites only the wrong numbers, and
reports composite inertias.

This package holds the massprops command (check, report, fix, merge-fixed,
view), the C++ library with its headers and CMake package
(find_package(massprops)), its mesh module (assimp, qhull) and the Python 3
module.
")
# Depends: from the libraries the installed binaries link, by dpkg-shlibdeps (dpkg-dev):
# tinyxml2, urdfdom, console-bridge (bin, library); assimp, qhull (mesh module); libstdc++, libc.
# toml++ is compiled in (header-only) and needs no package at run time.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_GENERATE_SHLIBS ON)
# libmassprops.so.0.1 is a public library in /usr/lib/<multiarch>: the shlibs file above, and
# ldconfig run by dpkg's trigger (lintian's lacks-ldconfig-trigger). cpack's postinst and postrm
# also call ldconfig (lintian: maintscript-calls-ldconfig, a warning; docs/install.md).
file(WRITE "${PROJECT_BINARY_DIR}/debian-control/triggers" "activate-noawait ldconfig\n")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA "${PROJECT_BINARY_DIR}/debian-control/triggers")
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
# What only some users need: Eigen's headers for find_package(massprops) (the one public
# dependency), the interpreter and numpy that `import massprops` runs in, and SQLite for
# `identify` on ROS 2 bags (loaded with dlopen, so dpkg-shlibdeps does not see it:
# src/io/sqlite_library.h).
set(recommends "libeigen3-dev, libsqlite3-0")
if(TARGET massprops-python)
  find_package(Python 3.7 QUIET COMPONENTS Interpreter)  # Python_EXECUTABLE: as python/ chose
  math(EXPR python_next "${Python_VERSION_MINOR} + 1")
  string(APPEND recommends ", python3 (>= ${Python_VERSION_MAJOR}.${Python_VERSION_MINOR}), "
         "python3 (<< ${Python_VERSION_MAJOR}.${python_next}), python3-numpy")
endif()
set(CPACK_DEBIAN_PACKAGE_RECOMMENDS "${recommends}")
include(CPack)

# package.xml (ROS 2, `colcon build`) states the version too: it must be this one.
file(STRINGS "${PROJECT_SOURCE_DIR}/package.xml" package_xml_version REGEX "<version>")
if(NOT package_xml_version MATCHES "<version>${PROJECT_VERSION}</version>")
  message(FATAL_ERROR "package.xml says ${package_xml_version}, project(VERSION) says "
                      "${PROJECT_VERSION}: make them equal")
endif()
