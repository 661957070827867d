#!/usr/bin/env bash
# A fleet's logs through `sinu diagnose`, in parallel on a workstation with GNU
# parallel, then one table across them: which effect, in how many units, with
# the estimates.
#   tools/diagnose_fleet.sh LOGS_DIR OUT_DIR [diagnose options...]
# LOGS_DIR holds one dataset folder (or raw recording *.raw) per flight; a
# flight's calib.json, when it has one, is LOGS_DIR/NAME/calib.json or
# LOGS_DIR/NAME.calib.json. Each diagnosis goes to OUT_DIR/NAME/ (report.md,
# diagnosis.json, model.json); the table to OUT_DIR/fleet.md. On a cluster the
# same per-flight command runs as a Slurm job array (README), then
# `tools/diagnose_fleet.sh --summarise OUT_DIR` writes the table.
set -euo pipefail
cd "$(dirname "$0")/.."
SINU="${SINU:-$PWD/build/release/firmware/sinu}"

summarise() {
  /usr/bin/python3 - "$1" <<'PY'
import collections, json, os, sys
out = sys.argv[1]
found, flights, failed = collections.defaultdict(list), 0, []
for name in sorted(os.listdir(out)):
    path = os.path.join(out, name, "diagnosis.json")
    if not os.path.isfile(path):
        if os.path.isdir(os.path.join(out, name)):
            failed.append(name)
        continue
    flights += 1
    d = json.load(open(path))
    for rnd in d.get("rounds", []):
        for c in rnd.get("candidates", []):
            if c.get("explains") and c["effect"] in d.get("missing_effects", []):
                found[c["effect"]].append((name, c["estimate"], c["sigma"]))
                break
lines = [f"# Fleet diagnosis: {flights} flights", "",
         "| effect | units | share | estimates (+- sigma, state units) |", "|---|---|---|---|"]
for effect, rows in sorted(found.items(), key=lambda kv: -len(kv[1])):
    est = "; ".join(f"{n}: [{', '.join(f'{v:.3g}+-{s:.2g}' for v, s in zip(e, sg))}]" for n, e, sg in rows)
    lines.append(f"| `{effect}` | {len(rows)} | {100 * len(rows) / max(1, flights):.0f} % | {est} |")
if not found:
    lines.append("| (none) | 0 | | |")
if failed:
    lines += ["", f"No diagnosis (see OUT_DIR/NAME/diagnose.log): {', '.join(failed)}"]
open(os.path.join(out, "fleet.md"), "w").write("\n".join(lines) + "\n")
print("\n".join(lines))
PY
}

if [ "${1:-}" = "--summarise" ]; then
  [ $# -eq 2 ] || { echo "usage: tools/diagnose_fleet.sh --summarise OUT_DIR" >&2; exit 2; }
  summarise "$2"
  exit 0
fi
[ $# -ge 2 ] || { echo "usage: tools/diagnose_fleet.sh LOGS_DIR OUT_DIR [diagnose options...]" >&2; exit 2; }
logs="$1" out="$2"
shift 2
[ -d "$logs" ] || { echo "diagnose_fleet.sh: $logs: not a folder" >&2; exit 2; }
[ -x "$SINU" ] || { echo "diagnose_fleet.sh: $SINU: build first (cmake --preset release && cmake --build --preset release)" >&2; exit 1; }
command -v parallel >/dev/null || { echo "diagnose_fleet.sh: GNU parallel is missing (tools/setup.sh installs it)" >&2; exit 1; }
mkdir -p "$out"

# One flight: its calib.json if it has one; diagnose --apply, quiet, one
# candidate replay at a time (parallel runs one flight per core).
one() {
  local flight="$1" out="$2"
  shift 2
  local name calib=()
  name="$(basename "$flight")"
  name="${name%.raw}"
  if [ -f "$flight/calib.json" ]; then calib=(--calib "$flight/calib.json");
  elif [ -f "${flight%.raw}.calib.json" ]; then calib=(--calib "${flight%.raw}.calib.json"); fi
  mkdir -p "$out/$name"
  "$SINU" diagnose --in "$flight" "${calib[@]}" --threads 1 --quiet --apply --out "$out/$name" "$@" \
    >"$out/$name/diagnose.log" 2>&1 || echo "diagnose_fleet.sh: $name failed (see $out/$name/diagnose.log)" >&2
}
export -f one
export SINU
bar=()
[ -t 2 ] && bar=(--bar)  # a progress bar on a terminal
find "$logs" -mindepth 1 -maxdepth 1 \( -type d -o -name '*.raw' \) | sort |
  parallel --will-cite "${bar[@]}" one {} "$out" "$@"
summarise "$out"
