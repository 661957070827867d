#!/usr/bin/env bash
# The main job on the bundled default: simulate the default 30-minute UAV
# flight and a 2-hour bench session of the same unit (seed 7; generated, not
# stored), calibrate the unit on the bench (wavelet denoiser, GM, Burg AR(3),
# Allan), record the flight as raw HAL traffic and read it back through the
# HAL and the drivers, then replay it through the INS/EKF with the GM and the
# AR sensor-error model, with GPS and with 30-s GPS outages, and print the
# navigation summaries and a GM-versus-AR report; then ask `sinu diagnose`
# whether the data show a physical effect the model lacks. Then the real
# drive and the real quadcopter in ../shared/ when present.
set -euo pipefail
cd "$(dirname "$0")/.."
SINU=build/release/firmware/sinu
[ -x "$SINU" ] || { echo "main_job.sh: build first: cmake --preset release && cmake --build --preset release" >&2; exit 1; }
out=build/main_job
mkdir -p "$out"
[ -f "$out/flight/imu.csv" ] || "$SINU" simulate flight --out "$out/flight" --seed 7 --hidden-out "$out/flight.hidden.json"
[ -f "$out/bench/imu.csv" ] || "$SINU" simulate static --out "$out/bench" --seed 7 --hours 2 --hidden-out "$out/bench.hidden.json"
[ -f "$out/calib.json" ] || "$SINU" calibrate --in "$out/bench" --out "$out/calib.json" --report "$out/calibration" --quiet
# Record it as raw HAL traffic (emulated ICM-20948 registers + NMEA bytes);
# every replay below reads that recording through the HAL replay back ends and
# the drivers, as the board would have seen it.
"$SINU" convert "$out/flight" "$out/flight.raw"
# The default options: the turn-on biases, the receiver's slowly varying error
# and its latency are default states; the magnetometer's noise and the GNSS
# velocity's are learnt from the innovations.
t0=$(awk -F, 'NR==2 {print $1; exit}' "$out/flight/imu.csv")
outages=$(awk -v t="$t0" 'BEGIN {printf "%.1f:30,%.1f:30,%.1f:30,%.1f:30", t+300, t+700, t+1100, t+1500}')
for model in gm ar; do
  common=(--in "$out/flight.raw" --truth "$out/flight/truth.csv" --calib "$out/calib.json" --model "$model")
  "$SINU" replay "${common[@]}" --out "$out/replay_$model"
  "$SINU" replay "${common[@]}" --outage "$outages" --out "$out/outages_$model"
done
# The report: GM versus AR on the same flight (the paper's comparison).
field() { sed -n "s/^  \"$2\": \([-0-9.e+]*\),*$/\1/p" "$1/summary.json" | head -1; }
rmse() { sed -n "/\"rmse\"/,/}/s/^    \"$2\": \([-0-9.e+]*\),*$/\1/p" "$1/summary.json" | head -1; }
echo "report: GM versus Burg AR(3), calibrated on the bench session ($out/calib.json; $out/calibration/report.md)"
printf '  %-5s %-26s %-26s %s\n' model "pos_h RMSE with GPS [m]" "att RMSE with GPS [deg]" "30-s outages: max drift RMS [m]"
for model in gm ar; do
  printf '  %-5s %-26.3f %-26.3f %.2f\n' "$model" "$(rmse "$out/replay_$model" pos_h_m)" "$(rmse "$out/replay_$model" att_deg)" \
    "$(field "$out/outages_$model" outage_max_drift_h_rms_m)"
done
# The firmware as it flies: `sinu fly` on the emulated board (the flight's
# registers, its data-ready edges, its GPS bytes through a pty), flat out,
# with the calibration; its recording replays to the same navigation log.
"$SINU" convert "$out/flight.raw" "$out/flight_as_chip"
cat >"$out/fly.toml" <<TOML
[navigation]
calibration = "$out/calib.json"
[outputs.log]
path = "$out/fly_nav.csv"
TOML
"$SINU" fly --config "$out/fly.toml" --emulate "$out/flight_as_chip" --speed 0 --record "$out/fly.raw" \
  --health-period 0 --stats
"$SINU" replay --in "$out/fly.raw" --calib "$out/calib.json" --out "$out/fly_replay" --quiet
cmp -s "$out/fly_nav.csv" "$out/fly_replay/nav.csv" && echo "fly: the recording replays to the flight's log, bit for bit" \
  || echo "fly: WARNING: the recording's replay differs from the flight's log"
# Model against measurements: does the replayed flight show an effect the model lacks?
"$SINU" diagnose --in "$out/flight.raw" --truth "$out/flight/truth.csv" --calib "$out/calib.json" --model gm --rounds 1 \
  --out "$out/diagnose"
drive=../shared/data/real/drive_0708
if [ -d "$drive" ]; then
  "$SINU" inspect dataset "$drive"
  # A car, nothing said about it: the default vehicle auto finds it is one (the non-holonomic constraint
  # and zero-velocity updates from then on); ten 15-s GNSS outages every 45 s from 60 s after it first
  # moves faster than 3 m/s (truth.csv's speed, as the test RealLogs and docs/experiments.md).
  moving=$(awk -F, 'NR > 1 && sqrt($5 * $5 + $6 * $6) > 3 {print $1; exit}' "$drive/truth.csv")
  drive_outages=$(awk -v t="$moving" 'BEGIN {for (k = 0; k < 10; ++k) printf "%s%.3f:15", (k ? "," : ""), t + 60 + 45 * k}')
  "$SINU" replay --in "$drive" --outage "$drive_outages" --out "$out/drive_0708"
else
  echo "main_job.sh: $drive is absent; skipping the real drive" >&2
fi
uav=../shared/data/real/uav_log171
if [ -d "$uav" ]; then
  # A real quadcopter (ArduPilot log; truth.csv is the autopilot's own EKF, a peer).
  "$SINU" replay --in "$uav" --out "$out/uav_log171"
else
  echo "main_job.sh: $uav is absent; skipping the real quadcopter" >&2
fi
