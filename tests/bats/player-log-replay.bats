#!/usr/bin/env bats
# player-log replay serving the Radish logs of tests/data/radish to
# player-cat and player-log record over loopback. Scan counts are those of
# `player-log info` (910 FLASER in Intel, 4791 in Freiburg 079, 406 in CSAIL).

load helpers

radish="$repo_root/tests/data/radish"

teardown() {
  kill_left_running "${record_pid:-}" "${server_pid:-}"
}

replay() {
  start_replay "$BATS_TEST_TMPDIR/replay.log" -p 0 --bind 127.0.0.1 "$@"
  target="127.0.0.1:$server_port"
}

stop_replay() {
  kill -TERM "$server_pid"
  wait_for_exit "$server_pid"
  [ "$exit_status" -eq 0 ]
}

# laser_lines FILE: a Player log's laser:0 lines from the data time on (the
# header time and host differ between a converted and a served log).
laser_lines() {
  awk '$4 == "laser" && $5 == "00"' "$1" | cut -d' ' -f6-
}

@test "--burst delivers every scan of the three Radish logs, value for value" {
  for entry in intel-corrected:910 freiburg-079-corrected:4791 csail-corrected:406; do
    name="${entry%%:*}" scans="${entry##*:}"
    "$player_log" convert "$radish/$name.log.gz" -o "$BATS_TEST_TMPDIR/$name.player.log" 2>/dev/null
    replay "$radish/$name.log.gz" --burst
    timeout 60 "$player_cat" "$target" laser:0 -n "$scans" --format log >"$BATS_TEST_TMPDIR/$name.served.log"
    stop_replay
    [ "$(laser_lines "$BATS_TEST_TMPDIR/$name.served.log" | wc -l)" -eq "$scans" ]
    diff <(laser_lines "$BATS_TEST_TMPDIR/$name.player.log") <(laser_lines "$BATS_TEST_TMPDIR/$name.served.log")
  done
}

@test "--rate 50 delivers every scan of ten minutes of the Intel log in time" {
  # The window: lines logged up to 600 s after the first one (ODOM lines with
  # earlier times are interleaved; FLASER times only grow).
  expected="$(zcat "$radish/intel-corrected.log.gz" | awk '
    $1 == "PARAM" || $1 ~ /^#/ || NF < 3 { next }
    first == "" { first = $NF }
    $NF > first + 600 { exit }
    $1 == "FLASER" { n++ }
    END { print n }')"
  [ "$expected" -gt 100 ]
  replay "$radish/intel-corrected.log.gz" --rate 50 --duration 600
  start=$SECONDS
  timeout 40 "$player_cat" "$target" laser:0 -n "$expected" --format log >"$BATS_TEST_TMPDIR/window.log"
  elapsed=$((SECONDS - start))
  stop_replay
  [ "$(laser_lines "$BATS_TEST_TMPDIR/window.log" | wc -l)" -eq "$expected" ]
  # Paced by the log: 600 s at 50x is 12 s, not a burst.
  [ "$elapsed" -ge 9 ]
}

@test "record -> replay -> record gives the same data" {
  replay "$radish/intel-corrected.log.gz" --burst
  "$player_log" record "$target" laser:0 position:0 -o "$BATS_TEST_TMPDIR/first.log" -n 4000 2>/dev/null
  stop_replay
  replay "$BATS_TEST_TMPDIR/first.log" --burst
  "$player_log" record "$target" laser:0 position:0 -o "$BATS_TEST_TMPDIR/second.log" -n 4000 2>/dev/null
  stop_replay
  # Data lines from the device name on: interface, index, data time and every
  # field (sync lines mark when rounds came, which differs from run to run),
  # each device's in its own order. How two devices' lines interleave is not
  # data: it follows which device a round took first, and under --burst one
  # round may carry several queued samples of one device.
  for run in first second; do
    awk '$1 !~ /^#/ && $4 != "sync"' "$BATS_TEST_TMPDIR/$run.log" | cut -d' ' -f4- >"$BATS_TEST_TMPDIR/$run.data"
    for device in laser position; do
      grep "^$device " "$BATS_TEST_TMPDIR/$run.data" >"$BATS_TEST_TMPDIR/$run.$device" || true
    done
  done
  [ "$(wc -l <"$BATS_TEST_TMPDIR/first.data")" -eq 4000 ]
  # 189 scans among the first 4000 messages: the corrected poses Intel stamps 0
  # after each scan are served too, at interpolated times (lib/log/log_clock.hpp).
  [ "$(wc -l <"$BATS_TEST_TMPDIR/first.laser")" -gt 150 ]
  [ "$(( $(wc -l <"$BATS_TEST_TMPDIR/first.laser") + $(wc -l <"$BATS_TEST_TMPDIR/first.position") ))" -eq 4000 ]
  # Both recordings stop at 4000 messages, so where the interleaving differs
  # near the end one may hold a few more of a device: the shorter sequence
  # must be the start of the longer, and nearly all of it.
  for device in laser position; do
    first_count=$(wc -l <"$BATS_TEST_TMPDIR/first.$device")
    second_count=$(wc -l <"$BATS_TEST_TMPDIR/second.$device")
    common=$(( first_count < second_count ? first_count : second_count ))
    longer=$(( first_count + second_count - common ))
    [ "$(( common * 100 ))" -ge "$(( longer * 95 ))" ]
    diff <(head -n "$common" "$BATS_TEST_TMPDIR/first.$device") <(head -n "$common" "$BATS_TEST_TMPDIR/second.$device")
  done
}

@test "--loop --start --duration replays the same window again" {
  replay "$radish/freiburg-079-corrected.log.gz" --burst --loop --start 100 --duration 20
  timeout 60 "$player_cat" "$target" laser:0 -n 400 --format log >"$BATS_TEST_TMPDIR/loop.log"
  stop_replay
  laser_lines "$BATS_TEST_TMPDIR/loop.log" | cut -d' ' -f1 >"$BATS_TEST_TMPDIR/times"
  first="$(head -n 1 "$BATS_TEST_TMPDIR/times")"
  # Data times start 100 s in (the log starts at 0.23 s) ...
  awk -v t="$first" 'BEGIN { exit !(t >= 100 && t < 101.5) }'
  # ... and come back to the first one when the window starts again.
  [ "$(grep -c -x -F "$first" "$BATS_TEST_TMPDIR/times")" -ge 2 ]
  awk '{ if ($1 > max) max = $1 } END { exit !(max < 121) }' "$BATS_TEST_TMPDIR/times"
}

@test "--devices serves only those; unknown devices and files are errors" {
  replay "$radish/intel-corrected.log.gz" --devices laser:0
  run --separate-stderr "$player_cat" "$target" --list
  stop_replay
  [ "$status" -eq 0 ]
  [[ "$output" == *"laser:0"* ]]
  [[ "$output" != *"position:0"* ]]

  run --separate-stderr "$player_log" replay "$radish/intel-corrected.log.gz" -p 0 --devices sonar:3
  [ "$status" -eq 2 ]
  [[ "$stderr" == *"has no sonar:3 to replay (it has position:0, laser:0, truth:0)"* ]]
  run --separate-stderr "$player_log" replay "$BATS_TEST_TMPDIR/missing.log" -p 0
  [ "$status" -eq 1 ]
  run --separate-stderr "$player_log" replay "$radish/intel-corrected.log.gz" -p 0 --rate 0
  [ "$status" -eq 2 ]
}
