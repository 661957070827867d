#!/usr/bin/env bash
# The paper's experiments (Table 5: slower GPS updates; Table 6: outages at
# 8 places), GM versus AR, on a simulated 50-minute flight whose IMU has the
# periodic-random error, with calib.json from a simulated static session of
# the same unit (same seed). Usage: tools/paper_experiments.sh [SEED] [OUTDIR]
set -euo pipefail
cd "$(dirname "$0")/.."
SINU=build/release/firmware/sinu
seed=${1:-11}
d=${2:-build/paper_experiments}
mkdir -p "$d"
[ -f "$d/flight/imu.csv" ] || "$SINU" simulate flight --out "$d/flight" --seed "$seed" --duration 3000 --hidden-out "$d/flight_hidden.json"
[ -f "$d/static/imu.csv" ] || "$SINU" simulate static --out "$d/static" --seed "$seed" --hours 2 --hidden-out "$d/static_hidden.json"
# The paper's pipeline: calibrate the static session after the wavelet
# denoiser (db4, level-3 approximation: calibrate's default); replay runs the
# same denoiser in front of the INS (calib.json names it).
[ -f "$d/calib.json" ] || "$SINU" calibrate --in "$d/static" --out "$d/calib.json" --quiet
# accel_bias,gyro_bias: the per-power-on bias is not part of calib.json's
# zero-mean models; gps_position_bias: the receiver's correlated error.
# MAG=1 fuses the magnetometer too (the paper's filter is INS/GPS only).
mag=(--no-mag)
[ "${MAG:-0}" = 1 ] && mag=()
common=(--in "$d/flight" --calib "$d/calib.json" --gps-latency 0.045 --effects accel_bias,gyro_bias,gps_position_bias
        "${mag[@]}" --quiet)
for m in gm ar; do
  for p in 0.2 10 15 20 25 30; do
    "$SINU" replay "${common[@]}" --model "$m" --gps-period "$p" --out "$d/${m}_p$p"
  done
done
/usr/bin/python3 tools/paper_tables.py places "$d/flight/truth.csv" > "$d/places.txt"
for dur in 20 25 30; do
  list=$(awk -F, -v D="$dur" '{printf "%s%s:%s", (NR>1?",":""), $1, D}' "$d/places.txt")
  for m in gm ar; do
    "$SINU" replay "${common[@]}" --model "$m" --outage "$list" --out "$d/${m}_o$dur"
  done
done
echo "## Table 5 (seed $seed)"
/usr/bin/python3 tools/paper_tables.py table5 "$d"
echo "## Table 6 (seed $seed)"
/usr/bin/python3 tools/paper_tables.py table6 "$d"
