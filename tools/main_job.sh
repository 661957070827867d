#!/usr/bin/env bash
# The main job on the bundled default: simulate the default 30-minute UAV
# flight (seed 7; generated, not stored), replay it through the INS/EKF with
# the GM and the AR sensor-error model and print the navigation summaries;
# then the real drive in ../shared/ when it is present.
set -euo pipefail
cd "$(dirname "$0")/.."
SINU=build/release/firmware/sinu
[ -x "$SINU" ] || { echo "main_job.sh: build first: cmake --preset release && cmake --build --preset release" >&2; exit 1; }
out=build/main_job
mkdir -p "$out"
[ -f "$out/flight/imu.csv" ] || "$SINU" simulate flight --out "$out/flight" --seed 7 --hidden-out "$out/flight.hidden.json"
# Record it as raw HAL traffic (emulated ICM-20948 registers + NMEA bytes), then
# read the recording back through the HAL replay back ends and the drivers.
"$SINU" convert "$out/flight" "$out/flight.raw"
rm -rf "$out/flight_hal" && "$SINU" convert "$out/flight.raw" "$out/flight_hal"
cp "$out/flight/truth.csv" "$out/flight_hal/truth.csv"
for model in gm ar; do
  "$SINU" replay --in "$out/flight_hal" --model "$model" --effects accel_bias,gyro_bias --gps-latency 0.045 --out "$out/replay_$model"
done
drive=../shared/data/real/drive_0708
if [ -d "$drive" ]; then
  "$SINU" inspect dataset "$drive"
  "$SINU" replay --in "$drive" --model gm --effects accel_bias,gyro_bias --gps-latency 0.05 --lever-arm 0,-0.05,0 \
    --out "$out/drive_0708"
else
  echo "main_job.sh: $drive is absent; skipping the real drive" >&2
fi
