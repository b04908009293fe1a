# Installation layout and a Debian package through CPack: `cmake --build build --target package`.
install(DIRECTORY ${DEMOPLAN_RESOURCE_DIR}/gtamp DESTINATION ${DEMOPLAN_INSTALL_DATA_DIR})

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME demoplan)
set(CPACK_PACKAGE_CONTACT "demoplan developers")
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "Teach a robot cell a pick-and-place task from one video")
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)
include(CPack)
