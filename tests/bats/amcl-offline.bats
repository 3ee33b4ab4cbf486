#!/usr/bin/env bats
# amcl-offline on the Intel Research Lab log of tests/data/radish: a map from
# its corrected poses, odometry degraded by perturb, tracking from the true
# start pose, evaluated against the corrected poses.

load helpers

intel="$repo_root/tests/data/radish/intel-corrected.log.gz"

setup() {
  cd "$BATS_TEST_TMPDIR"
}

# json_number KEY.PATH < FILE
json_number() {
  python3 -c 'import json, sys
v = json.load(sys.stdin)
for k in sys.argv[1].split("."): v = v[k]
print(v)' "$1"
}

@test "map, perturb, localize and eval: tracking the Intel log within 0.15 m" {
  run --separate-stderr "$amcl_offline" map "$intel" -o intel.pgm --resolution 0.05
  [ "$status" -eq 0 ]
  [[ "$stderr" == *"from 910 scans"* ]]
  [ "$(head -c 2 intel.pgm)" = "P5" ]
  grep -q '^image: intel.pgm' intel.yaml
  grep -q '^resolution: 0.05' intel.yaml

  run --separate-stderr "$amcl_offline" perturb "$intel" -o odom.log --seed 1
  [ "$status" -eq 0 ]
  # Every line is still there; only odometry changed, the corrected poses stay.
  [ "$(wc -l <odom.log)" -eq "$(zcat "$intel" | wc -l)" ]
  ! cmp -s odom.log <(zcat "$intel")
  diff <(awk '$1 == "FLASER" { print $183, $184, $185 }' odom.log) \
       <(zcat "$intel" | awk '$1 == "FLASER" { print $183, $184, $185 }')

  run --separate-stderr "$amcl_offline" localize odom.log --map intel.yaml --init-pose truth -o estimate.csv --plot path.png
  [ "$status" -eq 0 ]
  [[ "$stderr" == *"910 scans"*"x real time"* ]]
  [ "$(head -n 1 estimate.csv)" = "time,x,y,yaw,std_x,std_y,std_yaw,particles,cov_xy" ]
  [ "$(wc -l <estimate.csv)" -eq 911 ]
  [ "$(head -c 4 path.png | od -An -c | tr -d ' ')" = '211PNG' ]

  "$amcl_offline" eval estimate.csv --truth "$intel" --json >eval.json
  [ "$(json_number matched <eval.json)" -eq 910 ]
  python3 -c 'import json, math, sys
d = json.load(open("eval.json"))["all"]
assert d["position_rmse_m"] < 0.15, d
assert math.degrees(d["heading_rmse_rad"]) < 3.0, d
# The spread it claims means something: the truth inside the 2-sigma ellipse
# and heading interval at least 90 % of the scans, never far off outside it.
c = json.load(open("eval.json"))["coverage"]
assert c["rows"] == 910 and c["share"] >= 0.9 and c["confidently_wrong"] == 0, c'
  # The same run again gives the same rows: seeded.
  "$amcl_offline" localize odom.log --map intel.yaml --init-pose truth -o again.csv 2>/dev/null
  cmp estimate.csv again.csv
  # Both runs in one table, from their directory: a row each and one over all.
  mkdir runs && cp estimate.csv again.csv runs/
  run --separate-stderr "$amcl_offline" eval runs --truth "$intel" --format markdown
  [ "$status" -eq 0 ]
  [ "${#lines[@]}" -eq 5 ]
  [ "${lines[0]}" = "| estimate | truth | matched | rmse_m | max_m | rmse_deg | max_deg | converged_s | lost | in_2sigma |" ]
  [[ "${lines[2]}" == "| runs/again.csv | $intel | 910/910 | "* ]]
  [[ "${lines[4]}" == "| all 2 runs |  |  | "*" | 2/2 converged | "* ]]
}

@test "--global alone: a search over the free space, said on stderr, that finds the robot" {
  "$amcl_offline" map "$intel" -o intel.pgm --resolution 0.05 2>/dev/null
  "$amcl_offline" perturb "$intel" -o odom.log --seed 1 2>/dev/null
  run --separate-stderr "$amcl_offline" localize odom.log --map intel.yaml --global --seed 1 -o estimate.csv
  [ "$status" -eq 0 ]
  echo "$stderr"
  # 200 particles per m^2 of the map's free space (486 m^2), within 5000 to 100000.
  [[ "$stderr" =~ global\ start:\ ([0-9]+)\ particles\ \(200\ per\ m\^2 ]]
  [ "${BASH_REMATCH[1]}" -gt 50000 ] && [ "${BASH_REMATCH[1]}" -le 100000 ]
  [[ "$stderr" =~ found\ after\ ([0-9.]+)\ s\ of\ log ]]
  found_at=${BASH_REMATCH[1]}
  # Until the search narrowed down, the filter said it was lost, from the
  # first scan on (the log's first scan is at 32.9 s).
  [[ "$stderr" =~ warning:\ lost\ \(its\ own\ 2-sigma\ past\ 1\ m\ or\ 60\ deg\)\ from\ 32\.9\ s\ to\ ([0-9.]+)\ s ]]
  run --separate-stderr "$amcl_offline" eval estimate.csv --truth "$intel" --json
  [ "$status" -eq 0 ]
  # The evaluation agrees that it converged, and stayed within 0.15 m after.
  [ "$(json_number convergence_time_s <<<"$output" | cut -d. -f1)" -le "${found_at%.*}" ]
  python3 -c 'import sys; assert float(sys.argv[1]) < 0.15' \
    "$(json_number after_convergence.position_rmse_m <<<"$output")"
}

@test "the beam model tracks the Intel log as closely as the likelihood field" {
  "$amcl_offline" map "$intel" -o intel.pgm --resolution 0.05 2>/dev/null
  "$amcl_offline" perturb "$intel" -o odom.log --seed 1 2>/dev/null
  for model in likelihood beam; do
    "$amcl_offline" localize odom.log --map intel.yaml --init-pose truth --seed 1 --model "$model" \
      -o "$model.csv" 2>/dev/null
    "$amcl_offline" eval "$model.csv" --truth "$intel" --json >"$model.json" 2>/dev/null
  done
  # Measured over seeds 1-3: beam 0.066-0.071 m, likelihood field 0.073-0.078 m.
  # With the likelihood field's damping (0.2) the beam model was at 0.125-0.311 m.
  python3 -c 'import json
beam = json.load(open("beam.json"))["after_convergence"]
field = json.load(open("likelihood.json"))["after_convergence"]
assert beam["position_rmse_m"] < 0.1, beam
assert beam["position_rmse_m"] < field["position_rmse_m"] + 0.01, (beam, field)'
}

@test "people round the robot while it spins in place: the track holds" {
  "$amcl_offline" map "$intel" -o intel.pgm --resolution 0.05 2>/dev/null
  "$amcl_offline" perturb "$intel" -o odom.log --seed 1 2>/dev/null
  # Three stretches of 16 scans where the robot turns about five radians on
  # the spot; five people hide well over half of each of those scans.
  run "$BATS_TEST_DIRNAME/crowd_scans.py" odom.log crowded.log 96:111 328:343 603:618
  [ "$status" -eq 0 ]
  [[ "$output" =~ hid\ ([0-9]+)\ of\ ([0-9]+)\ readings ]]
  [ $((BASH_REMATCH[1] * 2)) -gt "${BASH_REMATCH[2]}" ]
  "$amcl_offline" localize crowded.log --map intel.yaml --init-pose truth --seed 1 -o estimate.csv 2>/dev/null
  "$amcl_offline" eval estimate.csv --truth "$intel" --json >eval.json 2>/dev/null
  python3 -c 'import json
d = json.load(open("eval.json"))["after_convergence"]
assert d["position_rmse_m"] < 0.15 and d["position_max_m"] < 0.5, d'
  # Scoring every reading, as 1.5 did, the crowds pull the estimate metres away.
  "$amcl_offline" localize crowded.log --map intel.yaml --init-pose truth --seed 1 --every-reading \
    -o every.csv 2>/dev/null
  "$amcl_offline" eval every.csv --truth "$intel" --json >every.json 2>/dev/null
  python3 -c 'import json
d = json.load(open("every.json"))["all"]
assert d["position_rmse_m"] > 2, d'
}

@test "dead reckoning alone is far off: the perturbation is real" {
  "$amcl_offline" perturb "$intel" -o odom.log --seed 1 2>/dev/null
  # The odometry of each scan as an 'estimate'.
  { echo "time,x,y,yaw"; awk '$1 == "FLASER" { n = $2; print $(NF-2) "," $(n+6) "," $(n+7) "," $(n+8) }' odom.log; } >odometry.csv
  "$amcl_offline" eval odometry.csv --truth "$intel" --json >eval.json
  python3 -c 'import json
d = json.load(open("eval.json"))["all"]
assert d["position_rmse_m"] > 5, d'
}

@test "json rows carry the CSV's keys" {
  "$amcl_offline" map "$intel" -o intel.pgm 2>/dev/null
  "$amcl_offline" localize "$intel" --map intel.yaml --init-pose truth --format json --particles 100,500 2>/dev/null | head -n 3 >rows.jsonl
  [ "$(wc -l <rows.jsonl)" -eq 3 ]
  python3 -c 'import json
for line in open("rows.jsonl"):
    assert sorted(json.loads(line)) == sorted(["time","x","y","yaw","std_x","std_y","std_yaw","particles","cov_xy"])'
}

@test "--format log writes Player localize lines that player-log reads" {
  "$amcl_offline" map "$intel" -o intel.pgm 2>/dev/null
  "$amcl_offline" localize "$intel" --map intel.yaml --init-pose truth --format log -o estimate.log 2>/dev/null
  run --separate-stderr "$player_log" info --strict --json estimate.log
  [ "$status" -eq 0 ]
  [ "$(json_number devices.localize:0.count <<<"$output")" -eq 910 ]
}

@test "the manual's post-hoc localization: player-serve -r with readlog and amcl, a client reads localize:0" {
  "$amcl_offline" map "$intel" -o intel.pgm 2>/dev/null
  "$player_log" convert "$intel" -o intel.log 2>/dev/null
  cat >bar.cfg <<CFG
position:0 (driver "readlog" index 0)
laser:0 (driver "readlog" index 0)
localize:0
(
  driver "amcl"
  position_index 0
  laser_index 0
  map_file "intel.yaml"
  init_pose [0.6 0.0 -20]
  init_pose_var [0.2 0.2 10]
)
CFG
  start_server server.log -p 0 --bind 127.0.0.1 -f 100 -r intel.log bar.cfg
  run --separate-stderr timeout 30 "$player_cat" "127.0.0.1:$server_port" localize:0 -n 20 --si --format json
  kill -TERM "$server_pid"
  wait_for_exit "$server_pid"
  [ "$status" -eq 0 ]
  [ "$(wc -l <<<"$output")" -eq 20 ]
  # The last update against the corrected pose of its scan. Estimates stamped
  # between scans are the predictions amcl publishes from odometry while
  # scans wait in its queue (a loaded machine), so the newest row stamped at
  # a scan's time is the one to judge.
  printf '%s\n' "$output" >rows.jsonl
  python3 - "$intel" <<'PY'
import gzip, json, math, sys
rows = [json.loads(line) for line in open("rows.jsonl")]
truth = {}
for line in gzip.open(sys.argv[1], "rt"):
    t = line.split()
    if t and t[0] == "FLASER":
        n = int(t[1])
        truth[round(float(t[-3]), 3)] = (float(t[n + 2]), float(t[n + 3]))
def scan_of(row):
    time = round(row["timestamp"], 3)
    nearest = min(truth, key=lambda k: abs(k - time))
    return nearest if abs(nearest - time) < 0.01 else None
updates = [row for row in rows if scan_of(row) is not None]
assert updates, [row["timestamp"] for row in rows]
last = updates[-1]["data"]
best = max(last["hypoths"][: last["hypoth_count"]], key=lambda h: h["alpha"])
x, y = truth[scan_of(updates[-1])]
error = math.hypot(best["mean"][0] - x, best["mean"][1] - y)
assert error < 0.5, (error, best, (x, y))
PY
}

@test "usage errors exit 2, unreadable inputs exit 1" {
  "$amcl_offline" map "$intel" -o intel.pgm 2>/dev/null
  run --separate-stderr "$amcl_offline" localize "$intel" --map intel.yaml
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"--init-pose"*"--global"* ]]
  run --separate-stderr "$amcl_offline" localize "$intel" --map intel.yaml --global --model sonar
  [ "$status" -eq 2 ]
  run --separate-stderr "$amcl_offline" localize "$intel" --map intel.yaml --init-pose 1,2
  [ "$status" -eq 2 ]
  run --separate-stderr "$amcl_offline" localize "$intel" --map missing.yaml --global
  [ "$status" -eq 1 ]
  run --separate-stderr "$amcl_offline" localize missing.log --map intel.yaml --global
  [ "$status" -eq 1 ]
  run --separate-stderr "$amcl_offline" eval missing.csv --truth "$intel"
  [ "$status" -eq 1 ]
}

# A recording whose first scan came before the truth device's first sample
# (player-log record subscribes to one device after another).
write_truth_after_first_scan() {
  cat >"$1" <<'LOG'
## Player version 1.5
## File version 0.0.0
0000000010.000 robot 6665 position 00 0000000010.000 +01.000 +02.000 +0.500 +00.000 +00.000 +00.000 0
0000000010.050 robot 6665 laser 00 0000000010.050 -1.5708 +1.5708 +1.5708 0003 1.000  0 2.000  0 3.000  0
0000000010.100 robot 6665 position 00 0000000010.100 +01.100 +02.000 +0.600 +00.000 +00.000 +00.000 0
0000000010.150 robot 6665 laser 00 0000000010.150 -1.5708 +1.5708 +1.5708 0003 4.000  0 5.000  0 6.000  0
0000000010.160 robot 6665 truth 00 0000000010.150 +05.000 +06.000 +0.700
0000000010.170 robot 6665 position 00 0000000010.150 +01.200 +02.000 +0.650 +00.000 +00.000 +00.000 0
LOG
}

@test "--init-pose truth starts at the first scan with a true pose and says what it skipped; no truth at all exits 1" {
  cave=(--map "$repo_root/data/worlds/cave.pnm" --scale 0.03 --negate --origin 0,0)
  write_truth_after_first_scan run.log
  run --separate-stderr "$amcl_offline" localize run.log "${cave[@]}" --init-pose truth -o estimate.csv
  [ "$status" -eq 0 ]
  [[ "$stderr" == *"warning: started at the first scan with a true pose; 1 scan before it skipped"* ]]
  [[ "$stderr" == *"no real-time factor: the scans span no time"* ]]  # one scan: not "0x real time"
  [ "$(wc -l <estimate.csv)" -eq 2 ]  # the header and the scan at 10.15
  [[ "$(sed -n 2p estimate.csv)" == 10.150000,5.0* || "$(sed -n 2p estimate.csv)" == 10.150000,4.9* ]]

  grep -v ' truth ' run.log >no-truth.log
  run --separate-stderr "$amcl_offline" localize no-truth.log "${cave[@]}" --init-pose truth -o estimate.csv
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"no-truth.log: no scan with odometry has a true pose to start from"* ]]
}

# Output files (docs/compatibility.md, "Output files"): never over an input,
# written through a temporary renamed at the end, .gz written compressed.

@test "map, perturb and localize refuse to write over their inputs; .gz outputs are gzip and read back" {
  zcat "$intel" | head -n 400 > small.log
  before="$(sha256sum < small.log)"
  ln -s small.log link.log
  "$amcl_offline" map small.log -o small.pgm 2>/dev/null
  for spelling in small.log ./small.log link.log; do
    run --separate-stderr "$amcl_offline" perturb small.log -o "$spelling"
    [ "$status" -eq 2 ]
    [[ "$stderr" == "amcl-offline: cannot write $spelling: it is the input small.log (the same file)"* ]]
    run "$amcl_offline" map small.log -o "$spelling"
    [ "$status" -eq 2 ]
    run "$amcl_offline" localize small.log --map small.yaml --init-pose truth -o "$spelling"
    [ "$status" -eq 2 ]
    run "$amcl_offline" localize small.log --map small.yaml --init-pose truth -o est.csv --plot "$spelling"
    [ "$status" -eq 2 ]
  done
  run "$amcl_offline" localize small.log --map small.yaml --init-pose truth -o small.yaml
  [ "$status" -eq 2 ]
  [ "$(sha256sum < small.log)" = "$before" ]
  grep -q '^image: small.pgm' small.yaml

  run --separate-stderr "$amcl_offline" perturb small.log -o noisy.log.gz --seed 3
  [ "$status" -eq 0 ]
  [ "$(head -c 2 noisy.log.gz | od -An -tx1 | tr -d ' ')" = "1f8b" ]
  [ "$(zcat noisy.log.gz | wc -l)" -eq 400 ]
  run --separate-stderr "$amcl_offline" localize noisy.log.gz --map small.yaml --init-pose truth -o est.csv.gz
  [ "$status" -eq 0 ]
  gzip -t est.csv.gz
  [ "$(zcat est.csv.gz | head -n 1 | cut -d, -f1-4)" = "time,x,y,yaw" ]
  run --separate-stderr "$amcl_offline" eval est.csv.gz --truth small.log
  [ "$status" -eq 0 ]
  [[ "$output" == *"matched"* ]]
  # Nothing half-written was left anywhere.
  [ -z "$(ls | grep '\.tmp-' || true)" ]
}

# ---- amcl-offline plan (wavefront): on the Intel lab map made from the log,
# start and goal where the robot really was. The map is made once per file.

plan_intel_map() {
  local map="$BATS_FILE_TMPDIR/plan-intel.yaml"
  [ -f "$map" ] || "$amcl_offline" map "$intel" -o "$BATS_FILE_TMPDIR/plan-intel.pgm" --resolution 0.05 2>/dev/null
  echo "$map"
}

# The log's true poses as a localize-style track: time,x,y,yaw.
plan_truth_track() {
  { echo "time,x,y,yaw"; zcat "$intel" | awk '$1 == "FLASER" { n = $2; print $(NF-2) "," $(n+3) "," $(n+4) "," $(n+5) }'; } >"$1"
}

@test "plan: csv waypoints from the start to the goal on the Intel map, every row two numbers" {
  map="$(plan_intel_map)"
  run --separate-stderr "$amcl_offline" plan --map "$map" --start 12.3586,-18.8004 --goal 0.6,-0.03
  [ "$status" -eq 0 ]
  [ "${lines[0]}" = "x,y" ]
  [ "${lines[1]}" = "12.3586,-18.8004" ]
  [ "${lines[${#lines[@]}-1]}" = "0.6000,-0.0300" ]
  [ "${#lines[@]}" -ge 4 ]  # the corridors turn
  printf '%s\n' "${lines[@]:1}" | awk -F, 'NF != 2 || $1 !~ /^-?[0-9]+\.[0-9]+$/ || $2 !~ /^-?[0-9]+\.[0-9]+$/ { exit 1 }'
  [[ "$stderr" == *"waypoints"*"closest approach"*"(keeping 0.30 m)"* ]]
}

@test "plan: json carries waypoints, length and a clearance of at least radius + safety; --plot writes a PNG" {
  map="$(plan_intel_map)"
  run --separate-stderr "$amcl_offline" plan --map "$map" --start 12.3586,-18.8004 --goal 0.6,-0.03 \
    --robot-radius 0.2 --safety 0.1 --format json -o plan.json --plot plan.png
  [ "$status" -eq 0 ]
  [ "$(head -c 4 plan.png | od -An -c | tr -d ' ')" = '211PNG' ]
  python3 -c 'import json, math
d = json.load(open("plan.json"))
w = d["waypoints"]
assert w[0] == [12.3586, -18.8004] and w[-1] == [0.6, -0.03], w
length = sum(math.dist(a, b) for a, b in zip(w, w[1:]))
assert abs(length - d["length_m"]) < 1e-3, (length, d["length_m"])
assert d["length_m"] > math.dist(w[0], w[-1])
assert d["required_clearance_m"] == 0.3 and d["min_clearance_m"] >= 0.3 - 1e-4, d'
}

@test "plan: --track --at starts at the last estimate at or before that time" {
  map="$(plan_intel_map)"
  plan_truth_track track.csv
  expected="$(awk -F, 'NR > 1 && $1 <= 500 { p = sprintf("%.4f,%.4f", $2, $3) } END { print p }' track.csv)"
  run --separate-stderr "$amcl_offline" plan --map "$map" --track track.csv --at 500 --goal 0.6,-0.03
  [ "$status" -eq 0 ]
  [ "${lines[1]}" = "$expected" ]
  run --separate-stderr "$amcl_offline" plan --map "$map" --track track.csv --at 1 --goal 0.6,-0.03
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"track.csv: no estimate at or before 1 s"* ]]
}

@test "plan --compare: the driven path against the plan between its ends, text and json" {
  map="$(plan_intel_map)"
  plan_truth_track track.csv
  head -n 300 track.csv >part.csv
  run --separate-stderr "$amcl_offline" plan --map "$map" --track part.csv --compare --plot compare.png
  [ "$status" -eq 0 ]
  [[ "${lines[1]}" == "driven "* ]]
  [[ "${lines[2]}" == "planned "* ]]
  [[ "$output" == *"driven/planned length"* ]]
  [ "$(head -c 4 compare.png | od -An -c | tr -d ' ')" = '211PNG' ]
  "$amcl_offline" plan --map "$map" --track part.csv --compare --format json 2>/dev/null >compare.json
  python3 -c 'import csv, json, math
d = json.load(open("compare.json"))
rows = [(float(r["x"]), float(r["y"])) for r in csv.DictReader(open("part.csv"))]
driven = sum(math.dist(a, b) for a, b in zip(rows, rows[1:]))
assert abs(d["driven"]["length_m"] - driven) < 1e-3, (d, driven)
assert d["driven"]["estimates"] == len(rows)
w = d["planned"]["waypoints"]
assert math.dist(w[0], rows[0]) < 1e-3 and math.dist(w[-1], rows[-1]) < 1e-3
assert abs(d["length_ratio"] - d["driven"]["length_m"] / d["planned"]["length_m"]) < 1e-3
assert d["driven"]["length_m"] > d["planned"]["length_m"] and d["planned"]["min_clearance_m"] >= 0.3 - 1e-4, d'
}

@test "plan: no path exits 1 saying why; bad flags exit 2" {
  map="$(plan_intel_map)"
  run --separate-stderr "$amcl_offline" plan --map "$map" --start 0.6,-0.03 --goal 500,0
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"no path from (0.60, -0.03) to (500.00, 0.00): goal is outside the map"* ]]
  run --separate-stderr "$amcl_offline" plan --map "$map" --start -19,-23 --goal 0.6,-0.03
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"start is in an unknown cell"* ]]
  run --separate-stderr "$amcl_offline" plan --map "$map" --start 0.6,-0.03 --goal 12.3586,-18.8004 --robot-radius 1.5
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"start is "*" m from an occupied or unknown cell, closer than 1.65 m"* ]]
  [ -z "$output" ]

  # Two rooms with no door between them (a 20 x 10 PGM, 0.1 m per pixel).
  python3 -c 'import sys
rows = [[0 if c == 10 else 255 for c in range(20)] for r in range(10)]
sys.stdout.write("P2 20 10 255\n" + "\n".join(" ".join(map(str, r)) for r in rows) + "\n")' >rooms.pgm
  run --separate-stderr "$amcl_offline" plan --map rooms.pgm --scale 0.1 --start -0.5,0 --goal 0.5,0 --robot-radius 0.1 --safety 0
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"the goal cannot be reached: no path keeps 0.10 m"* ]]

  run --separate-stderr "$amcl_offline" plan --map "$map" --start 0.6,-0.03
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"--goal X,Y"* ]]
  run --separate-stderr "$amcl_offline" plan --map "$map" --start 0.6 --goal 1,1
  [ "$status" -eq 2 ]
  run --separate-stderr "$amcl_offline" plan --map "$map" --start 0,0 --track t.csv --at 3 --goal 1,1
  [ "$status" -eq 2 ]
  run --separate-stderr "$amcl_offline" plan --map "$map" --start 0,0 --goal 1,1 --format xml
  [ "$status" -eq 2 ]
  run --separate-stderr "$amcl_offline" plan --map "$map" --start 0,0 --goal 1,1 -o "$map"
  [ "$status" -eq 2 ]
  run "$amcl_offline" plan --help
  [ "$status" -eq 0 ]
  [[ "$output" == *"Exit status: 0 done; 1 no path"* ]]
}
