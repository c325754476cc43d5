#!/usr/bin/env bash
# scripts/switches.sh SECONDS [SCENARIO...]: every documented switch on every built-in
# real-size heart. Runs each scenario (default: normal, irregular, inconsistent and the
# pathology presets) once as written and once per switch below, each for SECONDS of simulated
# time on one thread, and prints one row per run: the exit code, blood lost and inside the wall,
# the inverted tetrahedra at the end, the ejection fraction and stroke volume averaged over the
# complete beats (n/a when none), the wall's largest departure from its rest shape, wall
# seconds, and the first line of the error when the run failed. Several runs go at once (JOBS,
# default: the number of cores). Results: results/switches/<scenario>/<switch>/.
# HEARTSIM=path/to/heartsim runs that executable instead of the release build; SWITCHES=a,b
# runs only the switches of those names.
# A long run, not a test: docs/reliability.md has the figures.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:?usage: scripts/switches.sh SECONDS [SCENARIO...]}
shift
scenarios=("$@")
if [ ${#scenarios[@]} -eq 0 ]; then
  scenarios=(normal irregular inconsistent anterior-infarct aortic-stenosis dilated-cardiomyopathy
             heart-failure-preserved-ef mitral-regurgitation)
fi
# One switch per run: "name|--set arguments" (name "as-written" is the scenario itself).
switches=(
  "as-written|"
  "two-way|circulation.two_way=true"
  "valves-timing|circulation.valves=timing"
  "valves-open|circulation.valves=open"
  "wall-slip-off|circulation.wall_slip=false"
  "rate-20|cycle.heart_rate_bpm=20"
  "rate-250|cycle.heart_rate_bpm=250"
  "start-block|blood.start=block"
  "start-chamber|blood.start=chamber"
  "start-vessel|blood.start=vessel"
  "atrial-fibrillation|circulation.atrial_contraction=false"
  "base-descent-max|circulation.base_descent=0.4"
  "radial-max|circulation.radial_shortening=0.3"
  "contractility-max|circulation.contractility_mmhg_per_ml=20"
  "open-loop|circulation.loop=false"
  "basal-segments|cycle.segments=[1,2,3,4,5,6]"
)
heartsim=${HEARTSIM:-}
if [ -z "$heartsim" ]; then
  scripts/install-deps.sh
  scripts/build.sh release heartsim
  heartsim=build/release/apps/heartsim
fi
jobs=${JOBS:-$(nproc)}
if [ -n "${SWITCHES:-}" ]; then
  chosen=()
  for sw in "${switches[@]}"; do
    [[ ",$SWITCHES," == *",${sw%%|*},"* ]] && chosen+=("$sw")
  done
  [ ${#chosen[@]} -gt 0 ] || { echo "scripts/switches.sh: SWITCHES=$SWITCHES names no switch" >&2; exit 2; }
  switches=("${chosen[@]}")
fi

one_run() {  # scenario, switch name, set argument
  local s=$1 name=$2 set=$3 out=results/switches/$1/$2 code=0 start
  mkdir -p "$out"
  local args=(run "$s" --duration "$seconds" --threads 1 --out "$out")
  [ -n "$set" ] && args+=(--set "$set")
  start=$(date +%s)
  "$heartsim" "${args[@]}" > "$out/stdout.txt" 2> "$out/stderr.txt" || code=$?
  local wall=$(( $(date +%s) - start ))
  python3 - "$s" "$name" "$code" "$wall" "$out" <<'EOF'
import json, sys
scenario, name, code, wall, out = sys.argv[1:]
def first_error():
    for line in open(f"{out}/stderr.txt", errors="replace"):
        if "error" in line:
            return line.strip()[:110]
    return ""
try:
    d = json.load(open(f"{out}/summary.json"))
except (OSError, ValueError):
    d = {}
def get(*path):
    v = d
    for p in path:
        v = v.get(p) if isinstance(v, dict) else None
    return v
def fmt(v, f="{:.2f}"):
    return "n/a" if v is None else f.format(v)
print(f"{scenario:27s} {name:20s} {code:>4s} {fmt(get('blood','lost'),'{}'):>5s} "
      f"{fmt(get('blood','inside_wall'),'{}'):>6s} {fmt(get('tissue','inverted_tets'),'{}'):>8s} "
      f"{fmt(get('heart','ejection_fraction')):>5s} {fmt(get('heart','stroke_volume_ml'),'{:.1f}'):>6s} "
      f"{fmt(get('tissue','rest_deviation_final_rel'),'{:.3f}'):>8s} {wall:>6s}  "
      f"{first_error() if code != '0' else ''}", flush=True)
EOF
}
export -f one_run
export heartsim seconds

printf '%-27s %-20s %4s %5s %6s %8s %5s %6s %8s %6s  %s\n' scenario switch exit lost inside \
  inverted EF SV_mL rest_dev wall_s error
for s in "${scenarios[@]}"; do
  for sw in "${switches[@]}"; do
    printf '%s\0%s\0%s\0' "$s" "${sw%%|*}" "${sw#*|}"
  done
done | xargs -0 -n 3 -P "$jobs" bash -c 'one_run "$@"' _
