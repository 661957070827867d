#!/usr/bin/env bash
# The companion computer's build, as CI checks it: cross-compile the board
# program for aarch64 (SINU_BOARD_ONLY: fly, record, bench, calibrate), run the
# target tests (estimator, drivers, HAL, outputs; not the 48-run Monte Carlo nor
# the longest alignment runs, which the preset leaves to the host) under qemu, run the
# program itself under qemu, build the arm64 .deb and check what it installs.
#   tools/cross_check.sh [aarch64|armhf]     (default aarch64)
# Installs what it needs with tools/setup.sh --cross (Debian packages only).
set -euo pipefail
cd "$(dirname "$0")/.."
preset="${1:-aarch64}"
case "$preset" in
  aarch64) arch=arm64 qemu=qemu-aarch64 ;;
  armhf) arch=armhf qemu=qemu-arm ;;
  *) echo "cross_check.sh: unknown target $preset (aarch64 or armhf)" >&2; exit 2 ;;
esac
fail() { echo "cross_check.sh: FAILED: $*" >&2; exit 1; }

tools/setup.sh --cross
cmake --preset "$preset" >/dev/null
cmake --build --preset "$preset"
ctest --preset "$preset"

build="build/$preset"
file "$build/firmware/sinu" | grep -q "ARM" || fail "$build/firmware/sinu is not an ARM executable"
# The program runs on the target's libc (Debian multiarch, -L /) and has only the board commands.
help="$("$qemu" -L / "$build/firmware/sinu" --help)"
for cmd in fly record bench calibrate; do grep -q "^  $cmd" <<<"$help" || fail "sinu --help lacks $cmd"; done
for cmd in simulate replay diagnose; do ! grep -q "^  $cmd" <<<"$help" || fail "the board build has host mode $cmd"; done
"$qemu" -L / "$build/firmware/sinu" fly --config firmware/board/package/sinu.toml --i2c /nonexistent/i2c-1 --duration 1 \
  2>"$build/fly_stderr.txt" && fail "sinu fly without an I2C bus exited 0"
grep -q "/nonexistent/i2c-1" "$build/fly_stderr.txt" || fail "sinu fly without its bus does not name it"

# The fly loop on the target's instruction set: five simulated minutes through the
# emulated board, flat out, under qemu; its navigation log against the host's
# replay of the same flight (aarch64 GCC fuses multiply-adds: not bit for bit).
host_sinu=build/release/firmware/sinu
if [ -x "$host_sinu" ]; then
  sim="$build/emulate_check"
  rm -rf "$sim" && mkdir -p "$sim"
  # The flight as the chip's registers give it (dataset -> recording -> dataset).
  "$host_sinu" simulate flight --out "$sim/sim" --seed 5 --duration 300 >/dev/null
  "$host_sinu" convert "$sim/sim" "$sim/flight.raw" >/dev/null
  "$host_sinu" convert "$sim/flight.raw" "$sim/flight" >/dev/null
  printf '[outputs.log]\npath = "%s"\n' "$sim/fly_nav.csv" >"$sim/fly.toml"
  "$qemu" -L / "$build/firmware/sinu" fly --config "$sim/fly.toml" --emulate "$sim/flight" --speed 0 --stats \
    --health-period 0 | tee "$sim/stats.txt"
  "$host_sinu" replay --in "$sim/flight" --out "$sim/replay" --quiet
  /usr/bin/python3 - "$sim/fly_nav.csv" "$sim/replay/nav.csv" <<'PY' || fail "the $preset fly loop differs from the host replay"
import csv, math, sys
a = list(csv.DictReader(open(sys.argv[1]))); b = {r["t"]: r for r in csv.DictReader(open(sys.argv[2]))}
rows = [(r, b[r["t"]]) for r in a if r["t"] in b]
# 1 cm / 1 mm/s: rounding differences (fused multiply-adds) stay far below the
# filter's own uncertainty; a wrong build (endianness, struct layout, a
# miscompiled loop) is metres off.
def diff_m(x, y):
    lat = math.radians(float(x["lat"]))
    return max(abs(float(x["lat"]) - float(y["lat"])) * 111e3, abs(float(x["lon"]) - float(y["lon"])) * 111e3 * math.cos(lat),
               abs(float(x["h"]) - float(y["h"])))
dp = max(diff_m(x, y) for x, y in rows) if rows else math.inf
print(f"{len(rows)} rows of {len(a)} compared with the host replay; largest position difference {dp:.2e} m")
sys.exit(0 if len(rows) > 0.9 * len(a) and dp < 0.01 else 1)
PY
else
  echo "no host build at $host_sinu: the emulated flight under qemu is skipped (build the release preset first)"
fi

# The package.
rm -f "$build"/sinu_*.deb
(cd "$build" && cpack -G DEB >/dev/null)
deb="$(ls "$build"/sinu_*_"$arch".deb)"
echo "== $deb"
dpkg-deb -I "$deb"
dpkg-deb -c "$deb"
[ "$(dpkg-deb -f "$deb" Architecture)" = "$arch" ] || fail "Architecture is not $arch"
dpkg-deb -f "$deb" Depends | grep -q "libgpiod2" || fail "Depends lacks libgpiod2 (shlibdeps)"
contents="$(dpkg-deb -c "$deb")"
for path in ./usr/bin/sinu ./etc/sinu/sinu.toml ./lib/systemd/system/sinu.service ./lib/udev/rules.d/60-sinu.rules; do
  grep -q " $path\$" <<<"$contents" || fail "$deb lacks $path"
done
root="$build/deb_root"
rm -rf "$root" && mkdir -p "$root"
dpkg-deb -R "$deb" "$root"
grep -qx "/etc/sinu/sinu.toml" "$root/DEBIAN/conffiles" || fail "/etc/sinu/sinu.toml is not a conffile"
for script in postinst prerm postrm; do
  [ -x "$root/DEBIAN/$script" ] || fail "$script missing or not executable"
  sh -n "$root/DEBIAN/$script" || fail "$script: syntax"
done
# The unit as systemd reads it. verify also checks that ExecStart names an
# executable: point it at the packaged binary (the one line changed).
if command -v systemd-analyze >/dev/null; then
  unit_dir="$build/unit_check"
  rm -rf "$unit_dir" && mkdir -p "$unit_dir"
  sed "s#^ExecStart=/usr/bin/sinu#ExecStart=$(realpath "$root")/usr/bin/sinu#" "$root/lib/systemd/system/sinu.service" \
    >"$unit_dir/sinu.service"
  systemd-analyze verify "$unit_dir/sinu.service" || fail "systemd-analyze verify sinu.service"
  echo "systemd-analyze verify: sinu.service OK"
else
  echo "systemd-analyze not available: the unit is not verified"
fi
echo "cross_check.sh: $preset OK ($deb)"
