#!/usr/bin/env bash
# scripts/soak.sh SECONDS [SCENARIO...]: runs each scenario (default: every built-in one with a
# heart) for SECONDS of simulated time with the release build, one after the other, and prints
# one row each: exit code, simulated and wall seconds, blood lost and inside the wall (at the
# end; a run that loses blood exits 3), the worst tetrahedron (most inverted at any step, worst
# volume error and smallest dihedral angle), the number of beats, the ejection fraction of the
# first and the last minute (or tenth of the run, when shorter) and its drift in points per
# 10 minutes (least squares over every beat). Results: results/soak/<scenario>/.
# HEARTSIM=path/to/heartsim runs that executable instead of the release build; THREADS=N sets
# each run's threads (default: the number of cores).
# A soak longer than a sitting goes on where it stopped: each run writes a checkpoint every
# CHECKPOINT_EVERY simulated seconds (default 60) into results/soak/<scenario>/part-<k>/, and
# RESUME=1 continues each scenario from its latest checkpoint in a new part (bitwise the run
# that never stopped: CliCheckpoint tests). The row then covers every part: metrics.csv rows
# joined at each resume's time, the worst tetrahedron from the last summary (the checkpoint
# carries the run's monitor), wall seconds summed over the parts.
# A long run, not a test: docs/reliability.md has the figures.
set -euo pipefail
cd "$(dirname "$0")/.."
seconds=${1:?usage: scripts/soak.sh SECONDS [SCENARIO...]}
shift
scenarios=("$@")
if [ ${#scenarios[@]} -eq 0 ]; then
  scenarios=(normal irregular inconsistent anterior-infarct aortic-stenosis dilated-cardiomyopathy
             heart-failure-preserved-ef mitral-regurgitation heart-only paper-chamber-beating
             paper-vessel-beating)
fi
# HEARTSIM=path/to/heartsim uses that build instead of building the release one.
heartsim=${HEARTSIM:-}
if [ -z "$heartsim" ]; then
  scripts/install-deps.sh
  scripts/build.sh release heartsim
  heartsim=build/release/apps/heartsim
fi
printf '%-28s %4s %8s %8s %5s %6s %8s %9s %8s %6s %8s %8s %10s\n' scenario exit sim_s wall_s lost inside \
  inverted vol_err min_dih beats EF_first EF_last drift/10min
# A soak's checkpoints, oldest first (by part, then by time).
checkpoints() { { ls "$1"/part-*/checkpoint_*.hsck 2>/dev/null || true; } | sort -t/ -k4,4V -k5,5; }
for s in "${scenarios[@]}"; do
  soak=results/soak/$s
  latest=
  if [ "${RESUME:-0}" = 1 ]; then
    latest=$(checkpoints "$soak" | tail -n 1)
  fi
  [ -n "$latest" ] || rm -rf "$soak"
  parts=$(ls -d "$soak"/part-* 2>/dev/null | wc -l || true)
  out=$soak/part-$((parts + 1))
  mkdir -p "$out"
  start=$(date +%s)
  echo "$start" > "$out/started_s.txt"
  code=0
  from=("$s")
  if [ -n "$latest" ]; then
    echo "$latest" > "$out/resumed_from.txt"
    from=(--resume "$latest")
  fi
  "$heartsim" run "${from[@]}" --duration "$seconds" --threads "${THREADS:-$(nproc)}" --out "$out" \
    --checkpoint-every "${CHECKPOINT_EVERY:-60}" > "$out/stdout.txt" 2> "$out/stderr.txt" || code=$?
  echo $(( $(date +%s) - start )) > "$out/wall_s.txt"
  # Only the newest two checkpoints are kept: a resume needs the last.
  checkpoints "$soak" | head -n -2 | xargs -r rm -f
  # Wall seconds over every part; a part that was stopped ran until its metrics.csv was last written.
  wall=0
  for part in "$soak"/part-*; do
    if [ -f "$part/wall_s.txt" ]; then wall=$((wall + $(cat "$part/wall_s.txt")))
    else wall=$((wall + $(stat -c %Y "$part/metrics.csv") - $(cat "$part/started_s.txt"))); fi
  done
  # The parts' rows joined: each part's rows up to the time the next one resumed from.
  metrics=$soak/metrics.csv
  : > "$metrics"
  for part in $(ls -d "$soak"/part-* | sort -t- -k2,2n); do
    next=$soak/part-$(( ${part##*-} + 1 ))
    until=1e300
    if [ -f "$next/resumed_from.txt" ]; then
      until=$(grep -o 'checkpoint_[0-9.]*s' "$next/resumed_from.txt" | grep -o '[0-9][0-9.]*[0-9]')
    fi
    awk -F, -v until="$until" -v header="$([ -s "$metrics" ] && echo 0 || echo 1)" '
      NR == 1 { for (i = 1; i <= NF; ++i) if ($i == "time_s") tc = i; if (header) print; next }
      $tc <= until + 1e-9 { print }' "$part/metrics.csv" >> "$metrics"
  done
  out=$(ls -d "$soak"/part-* | sort -t- -k2,2n | tail -n 1)
  # The smallest dihedral angle over the run is in the summary (there is none after a crash).
  dihedral=$(grep -o '"min_dihedral_deg": *[0-9.]*' "$out/summary.json" 2>/dev/null | grep -o '[0-9.]*$' || echo n/a)
  # Per beat (from one systole's start to the next): EF = (EDV - ESV) / EDV of the cavity volume.
  awk -F, -v name="$s" -v code="$code" -v wall="$wall" -v span="$seconds" -v dihedral="${dihedral:0:6}" '
    NR == 1 { for (i = 1; i <= NF; ++i) col[$i] = i; next }
    {
      t = $col["time_s"]; v = $col["cavity_volume_ml"]; phase = $col["wall_phase"]
      if ($col["inverted_tets"] > inverted) inverted = $col["inverted_tets"]
      if ($col["volume_error_max"] > volErr) volErr = $col["volume_error_max"]
      # Without blood (heart-only) there are no blood columns.
      lost = ("blood_lost" in col) ? $col["blood_lost"] : "n/a"
      inside = ("blood_inside_wall" in col) ? $col["blood_inside_wall"] : "n/a"
      last = t
      if (phase == "systole" && previous != "systole") {
        if (beatStart != "" && edv > 0) { n++; bt[n] = beatStart; ef[n] = 100 * (edv - esv) / edv }
        beatStart = t; edv = v; esv = v
      }
      if (beatStart != "") { if (v > edv) edv = v; if (v < esv) esv = v }
      previous = phase
    }
    END {
      window = span >= 600 ? 60 : span / 10
      for (k = 1; k <= n; ++k) {
        if (bt[k] < bt[1] + window) { f += ef[k]; nf++ }
        if (bt[k] >= last - window) { l += ef[k]; nl++ }
        sx += bt[k]; sy += ef[k]; sxx += bt[k] * bt[k]; sxy += bt[k] * ef[k]
      }
      slope = (n > 1 && n * sxx - sx * sx > 0) ? (n * sxy - sx * sy) / (n * sxx - sx * sx) : 0
      printf "%-28s %4d %8.1f %8d %5s %6s %8d %9.3f %8s %6d %8s %8s %10s\n", name, code, last, wall, lost, inside,
        inverted, volErr, dihedral, n, nf ? sprintf("%.1f", f / nf) : "n/a", nl ? sprintf("%.1f", l / nl) : "n/a",
        (n > 1 ? sprintf("%+.2f", slope * 600) : "n/a")
    }' "$metrics"
done
