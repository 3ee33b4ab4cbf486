#!/usr/bin/env bats
# player-view's pictures of a simulated robot: the Pioneer of simple.world
# stands at (2, 2) facing 45 degrees in Player 1.5's cave. The picture is
# checked by its pixels (tests/bats/view_pixels.py): the map's walls where
# the map has them, the laser's points on those walls, the robot at the centre.

load helpers

view_pixels="$repo_root/tests/bats/view_pixels.py"

teardown() {
  kill_left_running "${server_pid:-}" "${view_pid:-}"
}

start_simulator() {
  start_server "$BATS_TEST_TMPDIR/serve.err" -s "$repo_root/data/worlds/simple.world" -p 0
}

@test "a snapshot of the simulated robot shows the cave's walls, the scan on them and the robot" {
  start_simulator
  run --separate-stderr timeout 60 "$player_view" "127.0.0.1:$server_port" --snapshot "$BATS_TEST_TMPDIR/robot.png" \
    --after 1 --size 400x400 --span 8 --map "$repo_root/data/worlds/cave.yaml"
  echo "$stderr"
  [ "$status" -eq 0 ]
  [ -z "$stderr" ]
  run python3 "$view_pixels" walls "$BATS_TEST_TMPDIR/robot.png" "$repo_root/data/worlds/cave.pnm" 0.03 2 2 8
  echo "$output"
  [ "$status" -eq 0 ]
  # (1.86, 2): inside the robot's box, clear of its heading line, drawn red.
  run python3 "$view_pixels" pixel "$BATS_TEST_TMPDIR/robot.png" 193 200
  [ "$output" = "220 30 30" ]
  stop_cleanly "$server_pid"
}

@test "a map image placed with --scale --negate --origin draws the same walls as its YAML" {
  start_simulator
  run --separate-stderr timeout 60 "$player_view" "127.0.0.1:$server_port" laser:0 truth:0 \
    --snapshot "$BATS_TEST_TMPDIR/robot.png" --after 0.5 --size 400x400 --span 8 \
    --map "$repo_root/data/worlds/cave.pnm" --scale 0.03 --negate --origin 0,0
  echo "$stderr"
  [ "$status" -eq 0 ]
  run python3 "$view_pixels" walls "$BATS_TEST_TMPDIR/robot.png" "$repo_root/data/worlds/cave.pnm" 0.03 2 2 8
  echo "$output"
  [ "$status" -eq 0 ]
  stop_cleanly "$server_pid"
}

@test "--record writes a numbered picture every interval and names it on stdout" {
  start_simulator
  run --separate-stderr timeout 60 "$player_view" "127.0.0.1:$server_port" --record "$BATS_TEST_TMPDIR/frames" \
    --every 0.2 --count 3 --size 200x150
  [ "$status" -eq 0 ]
  [ "${lines[*]}" = "$BATS_TEST_TMPDIR/frames/frame-000001.png $BATS_TEST_TMPDIR/frames/frame-000002.png $BATS_TEST_TMPDIR/frames/frame-000003.png" ]
  for n in 1 2 3; do
    run python3 "$view_pixels" pixel "$BATS_TEST_TMPDIR/frames/frame-00000$n.png" 199 149
    [ "$status" -eq 0 ]
  done
  stop_cleanly "$server_pid"
}

@test "an unreachable server is named with the reason, exit 1" {
  # A port that was free a moment ago: nothing listens there.
  port="$(python3 -c 'import socket; s=socket.socket(); s.bind(("127.0.0.1", 0)); print(s.getsockname()[1])')"
  run --separate-stderr "$player_view" "127.0.0.1:$port" --snapshot "$BATS_TEST_TMPDIR/x.png" --timeout 5
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"player-view: cannot connect to 127.0.0.1:$port: Connection refused"* ]]
  [ ! -e "$BATS_TEST_TMPDIR/x.png" ]
}

@test "a named device the server does not have is refused, with the server's list, exit 1" {
  start_simulator
  run --separate-stderr timeout 60 "$player_view" "127.0.0.1:$server_port" laser:0 fiducial:3 \
    --snapshot "$BATS_TEST_TMPDIR/x.png"
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"has no device fiducial:3"* ]]
  [[ "$stderr" == *"laser:0"* ]]
  [ ! -e "$BATS_TEST_TMPDIR/x.png" ]
  stop_cleanly "$server_pid"
}

@test "usage errors name the flag, exit 2" {
  run --separate-stderr "$player_view" --snapshot out.png --every 1
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"--every"* ]]
  run --separate-stderr "$player_view" --scale 0.03 --snapshot out.png
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"--scale is the map image's metres per pixel: it needs --map"* ]]
  run "$player_view" --help
  [ "$status" -eq 0 ]
  [[ "$output" == *"Exit status:"* ]]
}

# start_view LOG ARGS...: player-view ARGS... --http 0 in the background
# (view_pid); waits for the line that says where the page is (view_port).
start_view() {
  local log="$1"
  shift
  : >"$log"
  "$player_view" "$@" --http 0 2>"$log" &
  view_pid=$!
  wait_for_line --pid "$view_pid" "$log" 'serving http://127\.0\.0\.1:[0-9]+/' || return 1
  view_port="$(sed -n 's|.*serving http://127\.0\.0\.1:\([0-9][0-9]*\)/.*|\1|p' "$log" | head -n 1)"
}

@test "the live page is served on loopback and its WebSocket carries the scene, with the map first" {
  start_simulator
  start_view "$BATS_TEST_TMPDIR/view.err" "127.0.0.1:$server_port" --map "$repo_root/data/worlds/cave.yaml"
  run timeout 60 python3 "$repo_root/tests/bats/view_page.py" "$view_port" --map
  echo "$output"
  [ "$status" -eq 0 ]
  [[ "$output" == *"drive off"* ]]
  [[ "$output" == *"map 500x500 at 0.03 m"* ]]
  [[ "$output" == *"laser:0 "*" Hz"* ]]
  [[ "$output" == *"truth:0 "*" Hz"* ]]
  [[ "$output" == *"robot 2.0 2.0 0.785"* ]]
  # A second page gets the map first too, from the same Player connection.
  run timeout 60 python3 "$repo_root/tests/bats/view_page.py" "$view_port" --map
  echo "$output"
  [ "$status" -eq 0 ]
  stop_cleanly "$view_pid"
  ! grep -q warning "$BATS_TEST_TMPDIR/view.err"
  stop_cleanly "$server_pid"
}

@test "an HTTP port in use is named, exit 1; --bind beyond loopback warns" {
  start_simulator
  start_view "$BATS_TEST_TMPDIR/view.err" "127.0.0.1:$server_port" laser:0
  run --separate-stderr timeout 60 "$player_view" "127.0.0.1:$server_port" laser:0 --http "$view_port"
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"player-view: cannot serve HTTP on 127.0.0.1:$view_port: Address already in use"* ]]
  stop_cleanly "$view_pid"

  : >"$BATS_TEST_TMPDIR/bind.err"
  "$player_view" "127.0.0.1:$server_port" laser:0 --http 0 --bind 127.0.0.2 2>"$BATS_TEST_TMPDIR/bind.err" &
  view_pid=$!
  # Another loopback address: the warning is given for any address but the default.
  wait_for_line --pid "$view_pid" "$BATS_TEST_TMPDIR/bind.err" 'warning: the page listens on 127\.0\.0\.2, not 127\.0\.0\.1'
  stop_cleanly "$view_pid"
  stop_cleanly "$server_pid"
}

@test "--drive: the page drives the simulated robot, and a stop or a closed page stops it" {
  start_simulator
  start_view "$BATS_TEST_TMPDIR/view.err" "127.0.0.1:$server_port" --drive
  run timeout 90 python3 "$repo_root/tests/bats/view_drive.py" "$view_port"
  echo "$output"
  [ "$status" -eq 0 ]
  [[ "$output" == *"stopped after the page closed"* ]]
  stop_cleanly "$view_pid"
  stop_cleanly "$server_pid"
}

@test "--drive without a position device says so, exit 1" {
  start_simulator
  run --separate-stderr timeout 60 "$player_view" "127.0.0.1:$server_port" laser:0 --http 0 --drive
  [ "$status" -eq 1 ]
  [[ "$stderr" == *"--drive: no position device to drive on 127.0.0.1:$server_port"* ]]
  stop_cleanly "$server_pid"
}

@test "the live page says when the robot's server is lost, and shows the robot again when it returns" {
  start_simulator
  local port="$server_port"
  start_view "$BATS_TEST_TMPDIR/view.err" "127.0.0.1:$port" laser:0 truth:0
  stop_cleanly "$server_pid"
  wait_for_line --pid "$view_pid" "$BATS_TEST_TMPDIR/view.err" "lost 127\.0\.0\.1:$port .*reconnecting every second"
  run timeout 60 python3 "$repo_root/tests/bats/view_page.py" "$view_port" --expect-lost
  echo "$output"
  [ "$status" -eq 0 ]
  [[ "$output" == *"lost: the server closed the connection"* ]]
  # The same port again: the tool finds the server where it was.
  start_server "$BATS_TEST_TMPDIR/serve2.err" -s "$repo_root/data/worlds/simple.world" -p "$port"
  run timeout 60 python3 "$repo_root/tests/bats/view_page.py" "$view_port"
  echo "$output"
  [ "$status" -eq 0 ]
  [[ "$output" == *"laser:0 "* ]]
  stop_cleanly "$view_pid"
  stop_cleanly "$server_pid"
}
