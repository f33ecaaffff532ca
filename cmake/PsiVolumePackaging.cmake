# The Debian package paraview-psivolume, made by cpack's DEB generator for the ParaView of the
# Debian it is built on (scripts/build-deb.sh: cmake -DPSI_DEB_PACKAGE=ON -DCMAKE_INSTALL_PREFIX=/usr,
# then cpack -G DEB). Its files are the `runtime` component (the plugin, its modules and XML, the
# reference renderer, the Python package) plus the `debian` component below: the copyright file,
# the changelog, the lintian overrides and, where Debian's ParaView lists other packages' plugins
# from a directory (Debian 13 and later), a link to the plugin there. docs/install.md describes it.
option(PSI_DEB_PACKAGE "Configure the Debian package of the plugin (cpack -G DEB)" OFF)
if (NOT PSI_DEB_PACKAGE)
  return ()
endif ()
if (NOT CMAKE_INSTALL_PREFIX STREQUAL "/usr")
  message(FATAL_ERROR "PSI_DEB_PACKAGE: the package installs into /usr; configure with "
    "-DCMAKE_INSTALL_PREFIX=/usr (got ${CMAKE_INSTALL_PREFIX})")
endif ()

# The ParaView package built against: the package depends on exactly this version (a plugin
# loads only into its own ParaView; when Debian updates ParaView, apt removes the plugin rather
# than keep one that no longer loads).
execute_process(COMMAND dpkg-query -W "-f=\${Version}" paraview
  OUTPUT_VARIABLE _psi_paraview_deb RESULT_VARIABLE _psi_rc ERROR_QUIET
  OUTPUT_STRIP_TRAILING_WHITESPACE)
if (NOT _psi_rc EQUAL 0 OR _psi_paraview_deb STREQUAL "")
  message(FATAL_ERROR "PSI_DEB_PACKAGE: no Debian paraview package is installed")
endif ()
set(_psi_series "${ParaView_VERSION_MAJOR}.${ParaView_VERSION_MINOR}")
if (NOT _psi_paraview_deb MATCHES "^([0-9]+:)?${ParaView_VERSION_MAJOR}\\.${ParaView_VERSION_MINOR}[.~+-]")
  message(FATAL_ERROR "PSI_DEB_PACKAGE: the ParaView found (${ParaView_VERSION}, ${ParaView_DIR}) "
    "is not the installed Debian package paraview ${_psi_paraview_deb}")
endif ()

# Debian N's package sorts below unstable's, as Debian's own backports do (0.1-1~deb13 < 0.1-1);
# the changelog's distribution is the release's code name.
set(_psi_version_id "")
set(_psi_codename "unstable")
if (EXISTS "/etc/os-release")
  file(STRINGS "/etc/os-release" _psi_os REGEX "^(VERSION_ID|VERSION_CODENAME)=")
  foreach (_psi_line IN LISTS _psi_os)
    if (_psi_line MATCHES "^VERSION_ID=\"?([0-9]+)")
      set(_psi_version_id "${CMAKE_MATCH_1}")
    endif ()
  endforeach ()
  if (_psi_version_id)
    foreach (_psi_line IN LISTS _psi_os)
      if (_psi_line MATCHES "^VERSION_CODENAME=\"?([a-z]+)")
        set(_psi_codename "${CMAKE_MATCH_1}")
      endif ()
    endforeach ()
  endif ()
endif ()
set(_psi_release "1")
if (_psi_version_id)
  set(_psi_release "1~deb${_psi_version_id}")
endif ()

# The maintainer as Debian's own tools (dch, debmake) take it: DEBFULLNAME and DEBEMAIL, or
# PSI_DEB_MAINTAINER whole; read at every configuration (build-deb.sh configures every time).
set(_psi_name "$ENV{DEBFULLNAME}")
set(_psi_mail "$ENV{DEBEMAIL}")
if (_psi_name STREQUAL "")
  set(_psi_name "PsiVolume maintainers")
endif ()
if (_psi_mail STREQUAL "")
  set(_psi_mail "psivolume@localhost")
endif ()
set(PSI_DEB_MAINTAINER "$ENV{PSI_DEB_MAINTAINER}")
if (PSI_DEB_MAINTAINER STREQUAL "")
  set(PSI_DEB_MAINTAINER "${_psi_name} <${_psi_mail}>")
endif ()

# Where Debian's ParaView lists other packages' plugins from: from 5.13 on, the paraview.conf of
# its library directory names a directory whose plugins (and those of its subdirectories) are
# listed, not loaded. 5.11 reads only <executable's directory>/paraview.conf, which Debian does
# not ship: the maintainer scripts below add the plugin's XML to it.
execute_process(COMMAND dpkg-query -L paraview
  OUTPUT_VARIABLE _psi_paraview_files ERROR_QUIET)
string(REGEX MATCH "[^\n]*/paraview-${ParaView_VERSION_MAJOR}\\.${ParaView_VERSION_MINOR}/paraview\\.conf"
  _psi_debian_conf "${_psi_paraview_files}")
set(_psi_shared_plugins "")
if (_psi_debian_conf)
  file(STRINGS "${_psi_debian_conf}" _psi_conf_lines)
  foreach (_psi_line IN LISTS _psi_conf_lines)
    if (_psi_line MATCHES "^/" AND NOT _psi_line MATCHES "\\.xml$" AND NOT _psi_shared_plugins)
      set(_psi_shared_plugins "${_psi_line}")
    endif ()
  endforeach ()
  if (NOT _psi_shared_plugins MATCHES "^/usr/")
    message(FATAL_ERROR "PSI_DEB_PACKAGE: ${_psi_debian_conf} names no directory under /usr for "
      "other packages' plugins: PsiVolume could not be listed without changing paraview's files")
  endif ()
endif ()

set(_psi_deb "${CMAKE_CURRENT_BINARY_DIR}/debian")
file(REMOVE_RECURSE "${_psi_deb}")
file(MAKE_DIRECTORY "${_psi_deb}/scripts")
set(_psi_doc "${CMAKE_INSTALL_DATAROOTDIR}/doc/paraview-psivolume")

# The changelog (Debian Policy 12.7), compressed as policy wants (gzip -9n, no time stamp); its
# date is SOURCE_DATE_EPOCH's when set, for a reproducible package.
string(TIMESTAMP _psi_date "%a, %d %b %Y %H:%M:%S +0000" UTC)
file(WRITE "${_psi_deb}/changelog.Debian"
  "paraview-psivolume (${PROJECT_VERSION}-${_psi_release}) ${_psi_codename}; urgency=medium\n\n"
  "  * Built for ParaView ${_psi_paraview_deb}.\n\n"
  " -- ${PSI_DEB_MAINTAINER}  ${_psi_date}\n")
execute_process(COMMAND gzip -9nc "${_psi_deb}/changelog.Debian"
  OUTPUT_FILE "${_psi_deb}/changelog.Debian.gz" RESULT_VARIABLE _psi_rc)
if (NOT _psi_rc EQUAL 0)
  message(FATAL_ERROR "PSI_DEB_PACKAGE: gzip failed")
endif ()

# The copyright file (Debian Policy 12.5) in the machine-readable format, with LICENSE's text.
file(READ "${PROJECT_SOURCE_DIR}/LICENSE" _psi_license)
string(REGEX MATCH "Copyright \\(c\\) ([^\n]*)" _psi_holder "${_psi_license}")
set(_psi_holder "${CMAKE_MATCH_1}")
string(REGEX REPLACE "^.*Copyright \\(c\\) [^\n]*\n" "" _psi_text "${_psi_license}")
string(STRIP "${_psi_text}" _psi_text)
string(REPLACE "\n\n" "\n.\n" _psi_text "${_psi_text}")
string(REPLACE "\n" "\n " _psi_text " ${_psi_text}")
file(WRITE "${_psi_deb}/copyright"
  "Format: https://www.debian.org/doc/packaging-manuals/copyright-format/1.0/\n"
  "Upstream-Name: PsiVolume\n\n"
  "Files: *\n"
  "Copyright: ${_psi_holder}\n"
  "License: BSD-3-clause\n"
  "${_psi_text}\n")

# lintian's overrides, each with its reason (scripts/check-deb.sh fails on any other warning or
# error); none when the package has nothing to override.
set(_psi_overrides "")
if (_psi_codename STREQUAL "unstable")
  string(APPEND _psi_overrides
    "# Built from this repository for unstable, not uploaded to Debian: no bug (ITP) to close.\n"
    "paraview-psivolume: initial-upload-closes-no-bugs *\n")
endif ()
if (PSI_DEB_MAINTAINER MATCHES "<psivolume@localhost>$")
  string(APPEND _psi_overrides
    "# Built where no DEBEMAIL was set: the maintainer is the local placeholder\n"
    "# psivolume@localhost. Set DEBEMAIL (and DEBFULLNAME) for a reachable one.\n"
    "paraview-psivolume: bogus-mail-host Maintainer psivolume@localhost\n"
    "paraview-psivolume: bogus-mail-host-in-debian-changelog psivolume@localhost *\n")
endif ()
install(FILES "${_psi_deb}/copyright" "${_psi_deb}/changelog.Debian.gz"
  DESTINATION "${_psi_doc}" COMPONENT debian)
if (_psi_overrides)
  file(WRITE "${_psi_deb}/lintian-overrides" "${_psi_overrides}")
  install(FILES "${_psi_deb}/lintian-overrides"
    DESTINATION "${CMAKE_INSTALL_DATAROOTDIR}/lintian/overrides"
    RENAME paraview-psivolume COMPONENT debian)
endif ()
if (_psi_shared_plugins)
  # The plugin stays under /usr/lib (architecture-dependent files); ParaView lists it through the
  # link and the plugin finds its modules through it (RPATH $ORIGIN).
  string(REGEX REPLACE "^/usr/" "" _psi_shared_rel "${_psi_shared_plugins}")
  file(RELATIVE_PATH _psi_link_target "/usr/${_psi_shared_rel}" "/usr/${PSI_PLUGINS_DIR}/PsiVolume")
  file(MAKE_DIRECTORY "${_psi_deb}/link")
  file(CREATE_LINK "${_psi_link_target}" "${_psi_deb}/link/PsiVolume" SYMBOLIC)
  install(FILES "${_psi_deb}/link/PsiVolume" DESTINATION "${_psi_shared_rel}" COMPONENT debian)
endif ()

# Maintainer scripts. prerm: pvpython run as root writes byte code beside the package's modules;
# it goes with the package (py3clean, as dh_python3's scripts do). Debian 12: postinst adds the
# plugin's XML to /usr/bin/paraview.conf, which ParaView 5.11 reads at start (paraview, pvpython,
# pvbatch, pvserver) and Debian does not ship, and postrm takes it out again; a paraview.conf
# that a package owns is left alone (docs/install.md).
set(PSI_DEB_PACKAGE_DIR "/usr/${PSI_PYTHON_DESTINATION}/psivolume")
set(PSI_DEB_PARAVIEW_CONF "")
if (NOT _psi_debian_conf)
  set(PSI_DEB_PARAVIEW_CONF "/usr/${CMAKE_INSTALL_BINDIR}/paraview.conf")
endif ()
set(PSI_DEB_PLUGINS_XML "/usr/${PSI_PLUGINS_DIR}/PsiVolume.plugins.xml")
set(_psi_control "${_psi_deb}/scripts/prerm")
configure_file("${CMAKE_CURRENT_LIST_DIR}/deb/prerm.in" "${_psi_deb}/scripts/prerm" @ONLY)
if (PSI_DEB_PARAVIEW_CONF)
  configure_file("${CMAKE_CURRENT_LIST_DIR}/deb/postinst.in" "${_psi_deb}/scripts/postinst" @ONLY)
  configure_file("${CMAKE_CURRENT_LIST_DIR}/deb/postrm.in" "${_psi_deb}/scripts/postrm" @ONLY)
  list(APPEND _psi_control "${_psi_deb}/scripts/postinst" "${_psi_deb}/scripts/postrm")
endif ()
file(CHMOD ${_psi_control} PERMISSIONS OWNER_READ OWNER_WRITE OWNER_EXECUTE
  GROUP_READ GROUP_EXECUTE WORLD_READ WORLD_EXECUTE)

set(CPACK_GENERATOR "DEB")
set(CPACK_PACKAGE_NAME "paraview-psivolume")
set(CPACK_PACKAGE_VERSION "${PROJECT_VERSION}")
set(CPACK_PACKAGE_VENDOR "the PsiVolume authors")
set(CPACK_PACKAGE_CONTACT "${PSI_DEB_MAINTAINER}")
set(CPACK_PACKAGE_DIRECTORY "${CMAKE_CURRENT_BINARY_DIR}/package")
set(CPACK_PACKAGING_INSTALL_PREFIX "/usr")
set(CPACK_RESOURCE_FILE_LICENSE "${PROJECT_SOURCE_DIR}/LICENSE")
# Only the runtime and debian components (not the modules' development files), in one package.
set(CPACK_INSTALL_CMAKE_PROJECTS
  "${CMAKE_CURRENT_BINARY_DIR};PsiVolume;runtime;/"
  "${CMAKE_CURRENT_BINARY_DIR};PsiVolume;debian;/")
set(CPACK_STRIP_FILES ON)
set(CPACK_THREADS 1)
set(CPACK_DEBIAN_FILE_NAME "DEB-DEFAULT")
set(CPACK_DEBIAN_PACKAGE_RELEASE "${_psi_release}")
set(CPACK_DEBIAN_PACKAGE_MAINTAINER "${PSI_DEB_MAINTAINER}")
set(CPACK_DEBIAN_PACKAGE_SECTION "science")
set(CPACK_DEBIAN_PACKAGE_PRIORITY "optional")
set(CPACK_DEBIAN_COMPRESSION_TYPE "xz")
# Shared-library dependencies by dpkg-shlibdeps (the package's own modules found through
# RPATH $ORIGIN); ParaView's libraries carry no shlibs information on 5.11 and a version range
# from 5.13 on, which the exact dependency below narrows.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS
  "paraview (= ${_psi_paraview_deb}), python3-paraview (= ${_psi_paraview_deb}), python3:any, python3-numpy")
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${_psi_control})
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION ON)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY
  "'Psi Volume' representation for tetrahedral meshes in ParaView")
# The extended description, its lines as they are to be shown (CPack puts the summary first).
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION
  "Projected tetrahedra whose fragments integrate their own ray segment, by\n\
one of seven methods, with isosurfaces, adaptive sampling and depth\n\
peeling; a conforming tetrahedralization filter and a reader of\n\
tetrahedral .off files. Built for ParaView ${_psi_paraview_deb} only.")
include(CPack)
