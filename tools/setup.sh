#!/usr/bin/env bash
# Installs everything sinu needs on a fresh Debian bookworm machine, from
# Debian's packages only. Idempotent and non-interactive; run as root (or
# with sudo available). Usage: tools/setup.sh [--cross] [--reference]
#   --cross      also the aarch64/armhf cross compilers, qemu-user, the target
#                libraries (Debian multiarch) and the .deb tools (tools/cross_check.sh)
#   --reference  also the tools that regenerate test fixtures (pywt, Octave)
set -euo pipefail

packages=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev            # Eigen 3.4: fixed-size matrices in the estimator
  libgpiod-dev             # libgpiod 1.6 (v1 API): data-ready interrupts
  libgtest-dev libgmock-dev
  libbenchmark-dev
  nlohmann-json3-dev libcli11-dev libfmt-dev
  libtomlplusplus-dev      # toml++ 3.3: sinu fly's /etc/sinu/sinu.toml (firmware/board/config)
  clang libclang-rt-14-dev # libFuzzer targets, sanitizer runtimes
  python3 python3-numpy python3-matplotlib   # report plots (tools/*.py via /usr/bin/python3)
  parallel                 # GNU parallel: tools/diagnose_fleet.sh
  gpsd-clients             # gpsdecode: gpsd's NMEA decoder checks the NMEA output (Debian 12 ships it here, not in gpsd-tools)
  chromium                 # headless: test_diagnose_html_browser opens diagnose's report.html and checks its plots
)
for arg in "$@"; do
  case "$arg" in
    --cross)
      cross=1
      # Eigen, nlohmann-json and CLI11 are architecture-independent headers (above);
      # the libraries the program and its tests link come per target architecture.
      # systemd-analyze checks the unit, dpkg-dev + file let cpack run dpkg-shlibdeps.
      packages+=(g++-aarch64-linux-gnu g++-arm-linux-gnueabihf qemu-user systemd dpkg-dev file)
      for arch in arm64 armhf; do
        packages+=(libgpiod-dev:$arch libfmt-dev:$arch libtomlplusplus-dev:$arch
                   libgtest-dev:$arch libgmock-dev:$arch)
      done ;;
    --reference) packages+=(python3-pywt python3-scipy octave octave-signal) ;;
    *) echo "setup.sh: unknown option $arg" >&2; exit 2 ;;
  esac
done

SUDO=""
[ "$(id -u)" -eq 0 ] || SUDO="sudo"
if [ "${cross:-0}" = 1 ]; then  # target libraries come from Debian's multiarch packages
  for arch in arm64 armhf; do
    dpkg --print-foreign-architectures | grep -qx "$arch" || $SUDO dpkg --add-architecture "$arch"
  done
fi

missing=()
for p in "${packages[@]}"; do
  dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed" || missing+=("$p")
done
if [ ${#missing[@]} -eq 0 ]; then
  echo "setup.sh: all ${#packages[@]} packages already installed"
  exit 0
fi
echo "setup.sh: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
# A mirror caught mid-sync ("File has unexpected size ... Mirror sync in
# progress?") fails one index (seen: bookworm-security's armhf list, for
# days behind a caching proxy): try again, then go on with the indexes that
# did arrive; the install below fails, and says which package, if one is
# really missing.
for attempt in 1 2 3; do
  $SUDO apt-get update -qq && break
  if [ "$attempt" -eq 3 ]; then
    echo "setup.sh: warning: apt-get update failed 3 times; installing from the package lists it did fetch" >&2
    break
  fi
  echo "setup.sh: apt-get update failed (attempt $attempt of 3); retrying in 20 s" >&2
  sleep 20
done
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
