#!/usr/bin/env bash
# The main job on the bundled default. Grows as the modes land: today it
# validates and summarises the real drive in ../shared/ when it is present.
set -euo pipefail
cd "$(dirname "$0")/.."
SINU=build/release/firmware/sinu
[ -x "$SINU" ] || { echo "main_job.sh: build first: cmake --preset release && cmake --build --preset release" >&2; exit 1; }
drive=../shared/data/real/drive_0708
if [ -d "$drive" ]; then
  "$SINU" inspect dataset "$drive"
else
  echo "main_job.sh: $drive is absent; nothing to inspect yet" >&2
fi
