#!/usr/bin/env bats
# The navigation drivers through player-serve: lasercspace (manual 7.22) on
# a laser replayed from a real robot's log, vfh (manual 7.45) driving a
# simulated Pioneer to a goal sent from the shell.

load helpers

teardown() {
  kill_left_running "${server_pid:-}" "${cat_pid:-}" "${emulator_pid:-}"
}

# arrived FILE X Y: the last wavefront sample in FILE says stopped (stall 1)
# within 0.35 m of (X, Y) mm, after having driven (a stall 0 earlier).
arrived() {
  grep -q '"stall":0' "$1" &&
    tail -n 1 "$1" | jq -e --argjson x "$2" --argjson y "$3" \
      '.data.stall == 1 and ((.data.xpos - $x) * (.data.xpos - $x) + (.data.ypos - $y) * (.data.ypos - $y)) < 122500' \
      >/dev/null 2>&1
}

# near_goal FILE X Y: the last vfh sample in FILE (player-cat JSON) is
# stopped within 0.5 m of (X, Y) mm.
near_goal() {
  tail -n 1 "$1" | jq -e --argjson x "$2" --argjson y "$3" \
    '.data.xspeed == 0 and ((.data.xpos - $x) * (.data.xpos - $x) + (.data.ypos - $y) * (.data.ypos - $y)) < 250000' \
    >/dev/null 2>&1
}

@test "lasercspace shortens a replayed laser's beams by at least the robot's radius" {
  log="$BATS_TEST_TMPDIR/intel.log"
  "$player_log" convert "$repo_root/tests/data/radish/intel-lab.flirtlib.excerpt.log.gz" -o "$log" 2>/dev/null
  cat >"$BATS_TEST_TMPDIR/cspace.cfg" <<'CFG'
position:0 ( driver "readlog" index 0 )
laser:0 ( driver "readlog" index 0 )
laser:1 ( driver "lasercspace" laser 0 radius 0.3 )
CFG
  run "$player_serve" --check -r "$log" "$BATS_TEST_TMPDIR/cspace.cfg"
  [ "$status" -eq 0 ]
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 -r "$log" "$BATS_TEST_TMPDIR/cspace.cfg"
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" laser:0 laser:1 -n 10 --format json
  [ "$status" -eq 0 ]
  # Pairs of the same scan (same time): every free range is at most the
  # source range (in mm, range_res applied) less 300 mm, and never negative.
  run jq -s -e '
    group_by(.time) | map(select(length == 2) | sort_by(.index)) | length >= 3 and all(.[];
      (.[0].data) as $a | (.[1].data) as $b |
      (.[0].index == 0 and .[1].index == 1 and $b.range_res == 1) and
      ($a.range_count == $b.range_count) and
      ([range($a.range_count)] | all(. as $i |
        ($b.ranges[$i] >= 0) and
        ($b.ranges[$i] <= ([$a.ranges[$i] * $a.range_res - 300, 0] | max)))))' <<<"$output"
  [ "$status" -eq 0 ]
  stop_cleanly "$server_pid"
}

@test "lasercspace refuses to read itself, at --check" {
  cat >"$BATS_TEST_TMPDIR/self.cfg" <<'CFG'
laser:0 ( driver "lasercspace" laser 0 )
CFG
  run "$player_serve" --check "$BATS_TEST_TMPDIR/self.cfg"
  [ "$status" -ne 0 ]
  [[ "$output" == *"laser 0 is this device itself"* ]]
}

@test "vfh drives a simulated Pioneer to a goal sent from the shell" {
  cat >"$BATS_TEST_TMPDIR/vfh.cfg" <<'CFG'
position:1 ( driver "vfh" position_index 0 laser_index 0 max_speed 0.3 )
CFG
  start_server "$BATS_TEST_TMPDIR/serve.err" -s "$repo_root/data/worlds/simple.world" -p 0 --speedup 5 \
    "$BATS_TEST_TMPDIR/vfh.cfg"
  # A reader keeps vfh set up; the goal is in the odometric frame (the robot starts at its origin).
  "$player_cat" "localhost:$server_port" position:1 --format json >"$BATS_TEST_TMPDIR/vfh.jsonl" 2>"$BATS_TEST_TMPDIR/cat.err" &
  cat_pid=$!
  wait_for_nonempty --pid "$cat_pid" --log "$BATS_TEST_TMPDIR/cat.err" "$BATS_TEST_TMPDIR/vfh.jsonl"
  "$player_send" "localhost:$server_port" position:1 cmd xpos=2000 ypos=500 yaw=0 type=1 state=1
  wait_until --pid "$cat_pid" --timeout 120 --log "$BATS_TEST_TMPDIR/serve.err" "vfh to stop at (2, 0.5)" \
    near_goal "$BATS_TEST_TMPDIR/vfh.jsonl" 2000 500
  kill -TERM "$cat_pid"
  stop_cleanly "$server_pid"
}

@test "the navigation loop of data/config/nav-sim.cfg: amcl, vfh and wavefront take the robot to a goal" {
  start_server "$BATS_TEST_TMPDIR/serve.err" -s "$repo_root/data/worlds/simple.world" -p 0 --speedup 5 \
    "$repo_root/data/config/nav-sim.cfg"
  "$player_cat" "localhost:$server_port" position:2 --format json >"$BATS_TEST_TMPDIR/nav.jsonl" 2>"$BATS_TEST_TMPDIR/cat.err" &
  cat_pid=$!
  wait_for_nonempty --pid "$cat_pid" --log "$BATS_TEST_TMPDIR/cat.err" "$BATS_TEST_TMPDIR/nav.jsonl"
  "$player_send" "localhost:$server_port" position:2 cmd xpos=5000 ypos=2000 yaw=0 type=1 state=1
  wait_until --pid "$cat_pid" --timeout 120 --log "$BATS_TEST_TMPDIR/serve.err" "the robot at (5, 2)" \
    arrived "$BATS_TEST_TMPDIR/nav.jsonl" 5000 2000
  # The simulator's truth agrees with the estimate.
  run --separate-stderr timeout 30 "$player_cat" "localhost:$server_port" truth:0 -n 1 --format json
  [ "$status" -eq 0 ]
  jq -e '((.data.px - 5000) * (.data.px - 5000) + (.data.py - 2000) * (.data.py - 2000)) < 160000' <<<"$output"
  kill -TERM "$cat_pid"
  stop_cleanly "$server_pid"
}

@test "data/config/nav-pioneer.cfg: the same loop on p2os and sicklms200, against the emulated robot in the cave" {
  # The emulated Pioneer and laser in simple.world's cave, in its frame,
  # where the world puts the robot; the configuration is nav-sim.cfg's with
  # p2os and sicklms200 in place of the simulator, ports moved here.
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" \
    p2os pose=2,2,45 sicklms200 --link "$BATS_TEST_TMPDIR/robot" --link "$BATS_TEST_TMPDIR/laser" \
    --map "$repo_root/data/worlds/cave.yaml" --stats
  sed -e "s|\"/tmp/robot\"|\"$BATS_TEST_TMPDIR/robot\"|" -e "s|\"/tmp/laser\"|\"$BATS_TEST_TMPDIR/laser\"|" \
    -e "s|include \"nav-sim.cfg\"|include \"$repo_root/data/config/nav-sim.cfg\"|" \
    "$repo_root/data/config/nav-pioneer.cfg" >"$BATS_TEST_TMPDIR/nav-pioneer.cfg"
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/nav-pioneer.cfg"
  "$player_cat" "localhost:$server_port" position:2 --format json >"$BATS_TEST_TMPDIR/nav.jsonl" 2>"$BATS_TEST_TMPDIR/cat.err" &
  cat_pid=$!
  wait_for_nonempty --pid "$cat_pid" --log "$BATS_TEST_TMPDIR/cat.err" "$BATS_TEST_TMPDIR/nav.jsonl"
  # A Pioneer's motors start disabled (the simulator's do not): enabled
  # through vfh, which passes MOTOR_POWER down to p2os, as a 1.5 client did.
  "$player_send" "localhost:$server_port" position:1 req motor-power value=1
  "$player_send" "localhost:$server_port" position:2 cmd xpos=5000 ypos=2000 yaw=0 type=1 state=1
  wait_until --pid "$cat_pid" --timeout 240 --log "$BATS_TEST_TMPDIR/serve.err" "the robot at (5, 2)" \
    arrived "$BATS_TEST_TMPDIR/nav.jsonl" 5000 2000
  # The emulated robot itself is there: its true pose in the first stats
  # line written after the arrival, within 0.4 m of (5, 2).
  lines_then=$(grep -c ' at (' "$BATS_TEST_TMPDIR/emulate.err")
  stats_after() { [ "$(grep -c ' at (' "$BATS_TEST_TMPDIR/emulate.err")" -gt "$lines_then" ]; }
  wait_until --pid "$emulator_pid" "a stats line after the arrival" stats_after
  read -r true_x true_y < <(grep -o ' at ([0-9.-]*, [0-9.-]*' "$BATS_TEST_TMPDIR/emulate.err" | tail -n 1 | tr -d 'at(,')
  python3 -c 'import sys, math; assert math.hypot(float(sys.argv[1]) - 5, float(sys.argv[2]) - 2) < 0.4, sys.argv' \
    "$true_x" "$true_y"
  kill -TERM "$cat_pid"
  stop_cleanly "$server_pid"
  stop_cleanly "$emulator_pid"
}

@test "wavefront refuses a goal inside a wall at once and says why" {
  start_server "$BATS_TEST_TMPDIR/serve.err" -s "$repo_root/data/worlds/simple.world" -p 0 --speedup 5 \
    "$repo_root/data/config/nav-sim.cfg"
  "$player_cat" "localhost:$server_port" position:2 --format json >"$BATS_TEST_TMPDIR/nav.jsonl" 2>"$BATS_TEST_TMPDIR/cat.err" &
  cat_pid=$!
  wait_for_nonempty --pid "$cat_pid" --log "$BATS_TEST_TMPDIR/cat.err" "$BATS_TEST_TMPDIR/nav.jsonl"
  # (0.1, 0.1): in the cave's outer wall.
  "$player_send" "localhost:$server_port" position:2 cmd xpos=100 ypos=100 yaw=0 type=1 state=1
  wait_for_line --pid "$server_pid" "$BATS_TEST_TMPDIR/serve.err" "goal \(0\.1.*refused: "
  ! grep -q '"stall":0' "$BATS_TEST_TMPDIR/nav.jsonl"
  kill -TERM "$cat_pid"
  stop_cleanly "$server_pid"
}

@test "a Player 1.5 C client sends wavefront a goal and polls its stall flag until the robot is there" {
  goto_goal="$build_dir/examples/goto-goal/goto-goal"
  start_server "$BATS_TEST_TMPDIR/serve.err" -s "$repo_root/data/worlds/simple.world" -p 0 --speedup 5 \
    "$repo_root/data/config/nav-sim.cfg"
  run --separate-stderr timeout 180 "$goto_goal" 127.0.0.1 "$server_port" 2 8000 6000 0
  [ "$status" -eq 0 ]
  read -r _ _ x y yaw <<<"$output"
  [ $(((x - 8000) * (x - 8000) + (y - 6000) * (y - 6000))) -lt 122500 ]
  stop_cleanly "$server_pid"
}
