# The sinu .deb (cpack -G DEB in the build folder): /usr/bin/sinu, the default
# /etc/sinu/sinu.toml (a conffile), the systemd unit, a udev rule for the
# device groups, and maintainer scripts that create the user sinu. Built for
# the board by the cross presets (tools/cross_check.sh); paths as on bookworm.
set(_pkg ${CMAKE_CURRENT_LIST_DIR})
install(FILES ${_pkg}/sinu.toml DESTINATION /etc/sinu)
install(FILES ${_pkg}/sinu.service DESTINATION /lib/systemd/system)
install(FILES ${_pkg}/60-sinu.rules DESTINATION /lib/udev/rules.d)

set(CPACK_GENERATOR DEB)
set(CPACK_PACKAGE_NAME sinu)
set(CPACK_PACKAGE_DESCRIPTION_SUMMARY "GPS-aided MEMS inertial navigation unit (sinu fly as a systemd service)")
set(CPACK_PACKAGE_CONTACT "sinu maintainers <maintainers@users.noreply.h-seed-d7e4c23d.example>")
set(CPACK_PACKAGING_INSTALL_PREFIX /usr)
set(CPACK_DEBIAN_FILE_NAME DEB-DEFAULT)  # sinu_0.1.0_arm64.deb
set(CPACK_DEBIAN_PACKAGE_SECTION misc)
# The Debian architecture of the compiler's target (arm64, armhf, amd64), not
# the build machine's, which CPack would take from dpkg.
find_program(SINU_DPKG_ARCHITECTURE dpkg-architecture)
if(SINU_DPKG_ARCHITECTURE AND CMAKE_LIBRARY_ARCHITECTURE)
  execute_process(COMMAND ${SINU_DPKG_ARCHITECTURE} -t ${CMAKE_LIBRARY_ARCHITECTURE} -qDEB_HOST_ARCH
                  OUTPUT_VARIABLE CPACK_DEBIAN_PACKAGE_ARCHITECTURE OUTPUT_STRIP_TRAILING_WHITESPACE
                  ERROR_QUIET)
endif()
# Depends from the ELF's needed libraries, through the target architecture's
# multiarch packages (libgpiod2:arm64, ...); adduser for the postinst.
set(CPACK_DEBIAN_PACKAGE_SHLIBDEPS ON)
set(CPACK_DEBIAN_PACKAGE_DEPENDS adduser)
set(CPACK_DEBIAN_PACKAGE_CONTROL_EXTRA ${_pkg}/conffiles ${_pkg}/postinst ${_pkg}/prerm ${_pkg}/postrm)
set(CPACK_DEBIAN_PACKAGE_CONTROL_STRICT_PERMISSION TRUE)
include(CPack)
