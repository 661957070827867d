# Cross build for a Linux companion computer: aarch64-linux-gnu (Debian's g++-aarch64-linux-gnu).
# Use: cmake --preset aarch64
# Target libraries: Eigen, nlohmann-json, CLI11 are headers; libgpiod, fmt, toml++ and
# GoogleTest come from the target's multiarch -dev packages ('dpkg --add-architecture arm64',
# tools/setup.sh --cross).
set(CMAKE_SYSTEM_NAME Linux)
set(CMAKE_SYSTEM_PROCESSOR aarch64)
set(CMAKE_C_COMPILER aarch64-linux-gnu-gcc)
set(CMAKE_CXX_COMPILER aarch64-linux-gnu-g++)
set(CMAKE_FIND_ROOT_PATH /usr/aarch64-linux-gnu /usr/lib/aarch64-linux-gnu)
set(CMAKE_FIND_ROOT_PATH_MODE_PROGRAM NEVER)
set(CMAKE_FIND_ROOT_PATH_MODE_LIBRARY ONLY)
set(CMAKE_FIND_ROOT_PATH_MODE_INCLUDE BOTH)
set(CMAKE_FIND_ROOT_PATH_MODE_PACKAGE BOTH)
set(ENV{PKG_CONFIG_LIBDIR} "/usr/lib/aarch64-linux-gnu/pkgconfig:/usr/share/pkgconfig")
# Run target binaries (tests, 'sinu --help') on the host through qemu-user,
# with the target's own libc from Debian multiarch (libc6:arm64, pulled in by the
# -dev packages above): '-L /usr/aarch64-linux-gnu' would pair the cross toolchain's
# ld.so with that libc.so.6 of another glibc build, and threads hang.
set(CMAKE_CROSSCOMPILING_EMULATOR qemu-aarch64 -L /)
