#!/usr/bin/env bats
# player-serve -s WORLD: every example world of data/worlds starts and serves
# its devices; world-file errors exit 2 with file:line:col; pause and step.

load helpers

worlds="$repo_root/data/worlds"

teardown() {
  kill_left_running "${server_pid:-}"
}

# A TCP port free on 127.0.0.1 now.
free_port() {
  python3 -c 'import socket; s = socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])'
}

# serve_world WORLD ARGS...: player-serve -s WORLD on a free port of 127.0.0.1.
serve_world() {
  local world="$1"
  shift
  start_server "$BATS_TEST_TMPDIR/log" -s "$world" -p 0 --bind 127.0.0.1 "$@"
}

@test "simple.world: every device answers player-cat --once, stamped with simulation time" {
  serve_world "$worlds/simple.world"
  run "$player_cat" "127.0.0.1:$server_port" --list
  [ "$status" -eq 0 ]
  [ "$output" = "$(printf 'position:0 position\nsonar:0 sonar\nlaser:0 laser\ntruth:0 truth\nsimulation:0 simulation')" ]
  run "$player_cat" "127.0.0.1:$server_port" --once position:0 sonar:0 laser:0 truth:0 --format json
  [ "$status" -eq 0 ]
  [ "$(printf '%s\n' "$output" | wc -l)" -eq 4 ]
  # The world was loaded moments ago: its clock reads seconds, not the epoch.
  printf '%s\n' "$output" | python3 -c '
import json, sys
for line in sys.stdin:
    message = json.loads(line)
    assert message["timestamp"] < 600, line'
  run "$player_cat" "127.0.0.1:$server_port" --once truth:0 --field px --field py --field pa
  [[ "$output" == *"px=2000 py=2000 pa=45"* ]]
  grep -q "simulating $worlds/simple.world (Stage 1.3): 4 devices" "$BATS_TEST_TMPDIR/log"
}

@test "example-4a.world and example-4b.world (Stage 4) serve on the -p port" {
  for world in example-4a.world example-4b.world; do
    serve_world "$worlds/$world"
    run "$player_cat" "127.0.0.1:$server_port" --list
    [ "$status" -eq 0 ]
    [[ "$output" == *"position:0 position"* ]]
    [[ "$output" == *"position:1 position"* ]]
    run "$player_cat" "127.0.0.1:$server_port" --once position:0 position:1
    [ "$status" -eq 0 ]
    [ "$(printf '%s\n' "$output" | grep -c '^position:')" -eq 2 ]
    kill -TERM "$server_pid"
    wait_for_exit "$server_pid"
    [ "$exit_status" -eq 0 ]
  done
}

@test "example-13.world (Stage 1.3): each robot on its own port, as Player 1.5 served them" {
  # The world names ports 6665 and 6666: a copy names two that are free now.
  # Both drawn at once, so they differ; -p 0 might still draw one of them
  # after they are let go, so -p gets a third of the same draw.
  read -r first second third < <(python3 -c '
import socket
held = [socket.socket() for _ in range(3)]
for s in held: s.bind(("127.0.0.1", 0))
print(*(s.getsockname()[1] for s in held))')
  cp "$worlds/cave.pnm" "$BATS_TEST_TMPDIR/"
  sed -e "s/port 6665/port $first/" -e "s/port 6666/port $second/" "$worlds/example-13.world" \
    > "$BATS_TEST_TMPDIR/example-13.world"
  start_server "$BATS_TEST_TMPDIR/log" -s "$BATS_TEST_TMPDIR/example-13.world" -p "$third" --bind 127.0.0.1
  run "$player_cat" "127.0.0.1:$first" --list
  [ "$status" -eq 0 ]
  [[ "$output" == *"fiducial:0 fiducialfinder"* ]]
  [[ "$output" == *"blobfinder:0 blobfinder"* ]]
  run "$player_cat" "127.0.0.1:$first" --once position:0 laser:0 sonar:0 ptz:0 truth:0
  [ "$status" -eq 0 ]
  [ "$(printf '%s\n' "$output" | wc -l)" -eq 5 ]
  run "$player_cat" "127.0.0.1:$second" --list
  [ "$output" = "$(printf 'position:0 position\nlaser:0 laser\ntruth:0 truth')" ]
  run "$player_cat" "127.0.0.1:$second" --once truth:0 --field px --field py
  [[ "$output" == *"px=4000 py=2000"* ]]
  # The simulation device is on the -p port.
  run "$player_cat" "127.0.0.1:$third" --list
  [ "$output" = "simulation:0 simulation" ]
}

@test "--paused, then the simulation device steps the world one step at a time" {
  serve_world "$worlds/simple.world" --paused
  # While paused nothing is new: push-all shows the device's latest sample.
  run timeout 10 "$player_cat" "127.0.0.1:$server_port" --once --mode push-all simulation:0
  [ "$status" -eq 0 ]
  [[ "$output" == *"t=0.000000 data=1"* ]]
  run "$player_send" "127.0.0.1:$server_port" simulation:0 cmd cmd=2
  [ "$status" -eq 0 ]
  # A command is acted on at the next server cycle (10 ms on an idle machine).
  stepped() {
    [[ "$(timeout 10 "$player_cat" "127.0.0.1:$server_port" --once --mode push-all simulation:0)" == *"t=0.100000 data=1"* ]]
  }
  wait_until --pid "$server_pid" --log "$BATS_TEST_TMPDIR/log" "the simulation device to report one step (t=0.1)" stepped
  run timeout 10 "$player_cat" "127.0.0.1:$server_port" --duration 0.5 truth:0
  [ "$status" -eq 0 ]
  [ -z "$output" ]  # paused: nothing new
  run "$player_send" "127.0.0.1:$server_port" simulation:0 cmd cmd=0
  run timeout 10 "$player_cat" "127.0.0.1:$server_port" --once truth:0 --field px
  [ "$status" -eq 0 ]
  [[ "$output" == *"px=2000"* ]]
}

@test "--speedup 0 --sim-time runs as fast as it can and stops at the limit" {
  serve_world "$worlds/simple.world" --speedup 0 --sim-time 30
  wait_for_line --pid "$server_pid" "$BATS_TEST_TMPDIR/log" "the simulation stops at 30"
  run timeout 10 "$player_cat" "127.0.0.1:$server_port" --once --mode push-all simulation:0
  [[ "$output" == *"t=30.000000 data=1"* ]]
}

@test "--check -s lists the world's devices without serving" {
  run "$player_serve" --check -s "$worlds/example-13.world"
  [ "$status" -eq 0 ]
  [[ "$output" == *"11 devices, served on ports 6665, 6666"* ]]
  [[ "$output" == *'model "robot1.laser:0.fiducialfinder:0"'* ]]
}

@test "a .cfg with gz_* drivers adds devices on the same world" {
  printf 'position:5 ( driver "gz_position" gz_id "robot" )\nlaser:5 ( driver "gz_laser" gz_id "robot" )\n' \
    > "$BATS_TEST_TMPDIR/gz.cfg"
  serve_world "$worlds/simple.world" "$BATS_TEST_TMPDIR/gz.cfg"
  run "$player_cat" "127.0.0.1:$server_port" --once position:5 --field yaw
  [ "$status" -eq 0 ]
  [[ "$output" == *"position:5"*"yaw=0"* ]]  # odometry starts at (0, 0, 0)
  run "$player_cat" "127.0.0.1:$server_port" --once laser:5 --field range_count
  [ "$status" -eq 0 ]
  [[ "$output" == *"laser:5"*"range_count=361"* ]]
}

@test "writelog and amcl in a .cfg run on the simulated devices, on simulation time" {
  cat > "$BATS_TEST_TMPDIR/localize.cfg" <<EOF
null:0 ( driver "writelog" filename "$BATS_TEST_TMPDIR/sim.log" devices ["position:0" "laser:0"] alwayson 1 )
localize:0 ( driver "amcl" map_file "$worlds/cave.pnm" map_scale 0.03 map_negate 1 init_pose [2 2 45] init_pose_var [0.2 0.2 10] )
EOF
  serve_world "$worlds/simple.world" --speedup 4 "$BATS_TEST_TMPDIR/localize.cfg"
  run timeout 20 "$player_cat" "127.0.0.1:$server_port" --once localize:0 --si --format json
  [ "$status" -eq 0 ]
  # The estimate is where simple.world puts the robot: (2, 2), 45°.
  printf '%s\n' "$output" | python3 -c '
import json, math, sys
mean = json.loads(sys.stdin.readline())["data"]["hypoths"][0]["mean"]
assert abs(mean[0] - 2.0) < 0.2 and abs(mean[1] - 2.0) < 0.2, mean
assert abs(math.degrees(mean[2]) - 45) < 10, mean'
  kill -TERM "$server_pid"
  wait_for_exit "$server_pid"
  # writelog recorded the laser with simulation time stamps: seconds since the
  # world started (under 10^4 s here), not the wall clock's 1.7e9. Which
  # second the first scan lands in depends on how fast the machine runs.
  grep -q '^000000[0-9]\{4\}\.[0-9]* vm [0-9]* laser 00 000000[0-9]\{4\}\.' "$BATS_TEST_TMPDIR/sim.log"
}

@test "world-file errors are file:line:col, exit 2" {
  printf 'resolution 0.03\nposition ( pose [1 2 )\n' > "$BATS_TEST_TMPDIR/bad.world"
  run "$player_serve" -s "$BATS_TEST_TMPDIR/bad.world" -p 0 --bind 127.0.0.1
  [ "$status" -eq 2 ]
  [[ "$output" == *"$BATS_TEST_TMPDIR/bad.world:2:22: "* ]]
  printf 'size [10 10]\n\n  widget ( )\n' > "$BATS_TEST_TMPDIR/bad.world"
  run "$player_serve" --check -s "$BATS_TEST_TMPDIR/bad.world"
  [ "$status" -eq 2 ]
  [[ "$output" == *"$BATS_TEST_TMPDIR/bad.world:3:3: unknown macro or model type \"widget\""* ]]
  run "$player_serve" -s "$BATS_TEST_TMPDIR/missing.world" -p 0 --bind 127.0.0.1
  [ "$status" -eq 2 ]
  [[ "$output" == *"missing.world: cannot read the world file"* ]]
}

@test "a gz_* device naming no model is a configuration error at its option" {
  printf 'laser:5 ( driver "gz_laser" gz_id "nobody" )\n' > "$BATS_TEST_TMPDIR/gz.cfg"
  run "$player_serve" -s "$worlds/simple.world" -p 0 --bind 127.0.0.1 "$BATS_TEST_TMPDIR/gz.cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"gz.cfg:1:35: gz_laser: the world has no model named \"nobody\""* ]]
}

@test "simulation flags without -s, -r with -s, and -g are usage errors" {
  run "$player_serve" --speedup 2 "$BATS_TEST_TMPDIR/any.cfg"
  [ "$status" -eq 2 ]
  [[ "$output" == *"--speedup runs a simulation; it needs -s WORLD"* ]]
  run "$player_serve" -s "$worlds/simple.world" -r run.log
  [ "$status" -eq 2 ]
  [[ "$output" == *"-r and -s both set the server's clock"* ]]
  run "$player_serve" -g 0 -s "$worlds/simple.world"
  [ "$status" -eq 2 ]
  [[ "$output" == *"Gazebo (-g) is not available"* ]]
  run "$player_serve"
  [ "$status" -eq 2 ]
  [[ "$output" == *"nothing to serve"* ]]
}
