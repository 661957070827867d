# Cross build for a Linux companion computer: arm-linux-gnueabihf (Debian's g++-arm-linux-gnueabihf).
# Use: cmake --preset armhf
# Target libraries: Eigen, nlohmann-json, CLI11 are headers; libgpiod, fmt, toml++ and
# GoogleTest come from the target's multiarch -dev packages ('dpkg --add-architecture armhf',
# tools/setup.sh --cross).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR arm)
set(CMAKE_C_COMPILER arm-linux-gnueabihf-gcc)
set(CMAKE_CXX_COMPILER arm-linux-gnueabihf-g++)
set(CMAKE_FIND_ROOT_PATH /usr/arm-linux-gnueabihf /usr/lib/arm-linux-gnueabihf)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
set(ENV{PKG_CONFIG_LIBDIR} "/usr/lib/arm-linux-gnueabihf/pkgconfig:/usr/share/pkgconfig")
# Run target binaries (tests, 'sinu --help') on the host through qemu-user,
# with the target's own libc from Debian multiarch (libc6:armhf, pulled in by the
# -dev packages above): '-L /usr/arm-linux-gnueabihf' would pair the cross toolchain's
# ld.so with that libc.so.6 of another glibc build, and threads hang.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-arm -L /)
