#!/usr/bin/env bash
# Accuracy and speed of amcl-offline on the six bundled Radish logs: for each log,
# make a map from its corrected poses, degrade its odometry with `perturb`
# (seed 1, default Pioneer-like model), then localize with each laser model
# from the true initial pose (tracking) and from nothing (--global, augmented
# MCL on), and evaluate against the corrected poses. Prints a Markdown table,
# then a second one: likelihood-field tracking and global starts over perturb
# seeds 1-6 (each run with the filter seeded alike), to show how much the
# figures move with the odometry's luck. Global starts use the defaults
# (`--global` alone: the particle count is derived from the map's free area,
# and the search ends once one place holds the belief; docs/amcl.md).
# Örebro has no usable times: its runs are paired with the truth by scan order.
#
#   bench/amcl_accuracy.sh [BUILD_DIR]        (default: build)    about 6 minutes
set -euo pipefail
repo="$(cd "$(dirname "$0")/.." && pwd)"
build="${1:-$repo/build}"
offline="$build/tools/amcl-offline/amcl-offline"
work="$(mktemp -d)"
trap 'rm -rf "$work"' EXIT

field() { python3 -c 'import json,sys; d=json.load(sys.stdin); v=d
for k in sys.argv[1].split("."): v=v[k] if v is not None else None
print("-" if v is None else (round(v,3) if isinstance(v,float) else v))' "$1"; }

echo "| log | start | model | position RMSE (m) | max (m) | heading RMSE (deg) | converged after | lost (longest) | scans | wall (s) | real-time factor |"
echo "|---|---|---|---|---|---|---|---|---|---|---|"
logs=(intel-corrected freiburg-079-corrected freiburg-101-corrected edmonton-corrected csail-corrected orebro-corrected)
for name in "${logs[@]}"; do
  log="$repo/tests/data/radish/$name.log.gz"
  "$offline" map "$log" -o "$work/$name.pgm" 2>/dev/null
  "$offline" perturb "$log" -o "$work/$name.odom.log" --seed 1 2>/dev/null
  for run in "tracking likelihood" "tracking beam" "global likelihood"; do
    set -- $run
    start_args=(--init-pose truth)
    [ "$1" = global ] && start_args=(--global --seed 1)
    summary="$("$offline" localize "$work/$name.odom.log" --map "$work/$name.yaml" --model "$2" \
      "${start_args[@]}" -o "$work/estimate.csv" 2>&1 >/dev/null | tail -n 1)"
    "$offline" eval "$work/estimate.csv" --truth "$log" --json >"$work/eval.json"
    scans="$(sed -n 's/.*: \([0-9]*\) scans.*/\1/p' <<<"$summary")"
    wall="$(sed -n 's/.* in \([0-9.]*\) s wall.*/\1/p' <<<"$summary")"
    factor="$(sed -n 's/.*: \([0-9]*\)x real time.*/\1/p' <<<"$summary")"
    rmse="$(field after_convergence.position_rmse_m <"$work/eval.json")"
    max="$(field after_convergence.position_max_m <"$work/eval.json")"
    heading="$(python3 -c 'import json,sys,math; d=json.load(open(sys.argv[1]))["after_convergence"]; print(round(math.degrees(d["heading_rmse_rad"]),2) if d["count"] else "-")' "$work/eval.json")"
    conv_t="$(field convergence_time_s <"$work/eval.json")"
    conv_d="$(field convergence_distance_m <"$work/eval.json")"
    lost="$(field lost_episodes <"$work/eval.json") ($(field longest_lost_s <"$work/eval.json") s)"
    factor="${factor:+${factor}x}"
    echo "| $name | $1 | $2 | $rmse | $max | $heading | ${conv_t} s, ${conv_d} m | $lost | $scans | $wall | ${factor:-n/a (no usable times)} |"
  done
done

echo
echo "| log | start | seeds | position RMSE (m), range | worst max (m) | heading RMSE (deg), range | converged after (m), range | lost, total | longest lost (s) |"
echo "|---|---|---|---|---|---|---|---|---|"
for name in "${logs[@]}"; do
  log="$repo/tests/data/radish/$name.log.gz"
  for start in tracking global; do
    for seed in 1 2 3 4 5 6; do
      "$offline" perturb "$log" -o "$work/odom.log" --seed "$seed" 2>/dev/null
      start_args=(--init-pose truth)
      [ "$start" = global ] && start_args=(--global)
      "$offline" localize "$work/odom.log" --map "$work/$name.yaml" "${start_args[@]}" --seed "$seed" \
        -o "$work/estimate.csv" 2>/dev/null
      "$offline" eval "$work/estimate.csv" --truth "$log" --json >"$work/eval-$seed.json"
    done
    python3 - "$name" "$start" "$work" <<'PY'
import json, math, sys
name, start, work = sys.argv[1:4]
runs = [json.load(open(f"{work}/eval-{seed}.json")) for seed in range(1, 7)]
after = [r["after_convergence"] for r in runs if r["converged"]]
span = lambda values, digits: f"{min(values):.{digits}f}-{max(values):.{digits}f}" if values else "-"
print(f"| {name} | {start} | 1-6 ({len(after)} converged) "
      f"| {span([a['position_rmse_m'] for a in after], 3)} "
      f"| {max((a['position_max_m'] for a in after), default=float('nan')):.3f} "
      f"| {span([math.degrees(a['heading_rmse_rad']) for a in after], 2)} "
      f"| {span([r['convergence_distance_m'] for r in runs if r['converged']], 1)} "
      f"| {sum(r['lost_episodes'] for r in runs)} "
      f"| {max(r['longest_lost_s'] for r in runs):.1f} |")
PY
  done
done
