#!/usr/bin/env bash
# Builds the libFuzzer targets with Debian's clang, ASan and UBSan, and runs
# each for a bounded time. Exit status is non-zero on any finding.
#   tools/fuzz.sh [seconds-per-target]      (default 60)
# Seeds: the gpsd captures in ../shared/data/nmea-gpsd (when present) for the
# NMEA target, and a raw recording made from a small generated dataset for
# the recording target. Findings are written to build/fuzz/findings/.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds="${1:-60}"
build=build/fuzz
cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_CXX_COMPILER=clang++ \
  -DSINU_FUZZ=ON -DSINU_WERROR=ON -DSINU_BUILD_TESTS=OFF -DSINU_BUILD_BENCHMARKS=OFF >/dev/null
# The seed recording is made by `sinu convert`: use the release build's when it
# exists (CI builds it first), else build one here with the fuzz flags.
sinu_bin=build/release/firmware/sinu
if [ -x "$sinu_bin" ]; then
  cmake --build "$build" -j2 --target fuzz_nmea fuzz_recording
else
  cmake --build "$build" -j2 --target fuzz_nmea fuzz_recording sinu
  sinu_bin="$build/firmware/sinu"
fi

seeds="$build/seeds"
rm -rf "$seeds" && mkdir -p "$seeds/nmea" "$seeds/recording" "$build/findings"
if [ -d ../shared/data/nmea-gpsd ]; then cp ../shared/data/nmea-gpsd/*.log "$seeds/nmea/"; fi
printf '$GPGGA,101520.40,3024.51234,N,11421.12345,E,1,12,0.8,45.3,M,-2.1,M,,*51\r\n' >"$seeds/nmea/gga.txt"
data="$seeds/dataset"
mkdir -p "$data"
{
  echo "t,ax,ay,az,gx,gy,gz,mx,my,mz,temp"
  for k in $(seq 0 19); do echo "$((100 + k)).025,0.1,0,-9.8,0.01,0,0,20,0,40,25"; done
} >"$data/imu.csv"
printf '100.5,$GPGGA,101520.40,3024.51234,N,11421.12345,E,1,12,0.8,45.3,M,-2.1,M,,*51\n' >"$data/gps.nmea"
ASAN_OPTIONS=detect_leaks=0 "$sinu_bin" convert "$data" "$seeds/recording/small.raw" >/dev/null

status=0
for target in fuzz_nmea fuzz_recording; do
  corpus="$build/corpus/$target"
  mkdir -p "$corpus"
  seed_dir="$seeds/nmea"
  [ "$target" = fuzz_recording ] && seed_dir="$seeds/recording"
  echo "== $target for ${seconds} s"
  max_len=8192  # NMEA: long enough for many sentences, short enough for speed
  [ "$target" = fuzz_recording ] && max_len=65536
  if ! "$build/host_tests/fuzz/$target" -max_total_time="$seconds" -max_len="$max_len" -timeout=10 -rss_limit_mb=1024 \
      -artifact_prefix="$build/findings/$target-" -print_final_stats=1 "$corpus" "$seed_dir"; then
    echo "== $target: FINDING (see $build/findings/)"
    status=1
  fi
done
exit $status
