# Installation layout (FHS, XDG) and a Debian package through CPack:
# `cmake --build build --target package`. packaging/README.md says what the package holds and
# which lintian warnings are accepted.
include(GNUInstallDirs)
install(DIRECTORY ${DEMOPLAN_RESOURCE_DIR}/gtamp DESTINATION ${DEMOPLAN_INSTALL_DATA_DIR})
if(DEMOPLAN_BUILD_UI)
  install(FILES ${CMAKE_CURRENT_LIST_DIR}/org.demoplan.demoplan.desktop DESTINATION ${CMAKE_INSTALL_DATADIR}/applications)
  install(FILES ${CMAKE_CURRENT_LIST_DIR}/org.demoplan.demoplan.svg
          DESTINATION ${CMAKE_INSTALL_DATADIR}/icons/hicolor/scalable/apps)
  install(FILES ${CMAKE_CURRENT_LIST_DIR}/org.demoplan.demoplan.metainfo.xml DESTINATION ${CMAKE_INSTALL_DATADIR}/metainfo)
endif()
# Debian wants the copyright and a compressed changelog in /usr/share/doc/<package>.
set(DEMOPLAN_CHANGELOG_GZ ${CMAKE_CURRENT_BINARY_DIR}/changelog.gz)
add_custom_command(OUTPUT ${DEMOPLAN_CHANGELOG_GZ}
                   COMMAND gzip -9nc ${CMAKE_CURRENT_LIST_DIR}/changelog > ${DEMOPLAN_CHANGELOG_GZ}
                   DEPENDS ${CMAKE_CURRENT_LIST_DIR}/changelog)
add_custom_target(demoplan_changelog ALL DEPENDS ${DEMOPLAN_CHANGELOG_GZ})
# Manual pages, compressed as Debian wants them.
foreach(page demoplan.1 demoplan-cli.1)
  add_custom_command(OUTPUT ${CMAKE_CURRENT_BINARY_DIR}/${page}.gz
                     COMMAND gzip -9nc ${CMAKE_CURRENT_LIST_DIR}/${page} > ${CMAKE_CURRENT_BINARY_DIR}/${page}.gz
                     DEPENDS ${CMAKE_CURRENT_LIST_DIR}/${page})
  list(APPEND DEMOPLAN_MAN_PAGES ${CMAKE_CURRENT_BINARY_DIR}/${page}.gz)
endforeach()
add_custom_target(demoplan_man_pages ALL DEPENDS ${DEMOPLAN_MAN_PAGES})
install(FILES ${DEMOPLAN_MAN_PAGES} DESTINATION ${CMAKE_INSTALL_MANDIR}/man1)
install(FILES ${CMAKE_CURRENT_LIST_DIR}/copyright ${DEMOPLAN_CHANGELOG_GZ} DESTINATION ${CMAKE_INSTALL_DOCDIR})

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME demoplan)
set(CPACK_PACKAGE_VERSION ${PROJECT_VERSION})
set(CPACK_PACKAGE_CONTACT "demoplan developers <developers@demoplan.org>")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Teach a robot cell a pick-and-place task from one video")
set(CPACK_DEBIAN_PACKAGE_DESCRIPTION "An operator records a person moving known parts in front of a calibrated
camera. demoplan finds when the hand grasps and releases each part and the
part's pose at those moments, plans the robot's motion guided by the
demonstration and exports a timed program for the cell controller. This
package holds the desktop application, the command line and the bundled
benchmark data.")
set(CPACK_DEBIAN_PACKAGE_SECTION science)
set(CPACK_DEBIAN_PACKAGE_PRIORITY optional)
set(CPACK_DEBIAN_PACKAGE_HOMEPAGE "https://demoplan.org")
# Runtime dependencies computed from the binaries (dpkg-shlibdeps), not listed by hand.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
# ... except what Qt loads at run time, which no binary links: the platform plugins (xcb).
set(CPACK_DEBIAN_PACKAGE_DEPENDS "qt6-qpa-plugins")
set(CPACK_STRIP_FILES ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
include(CPack)
