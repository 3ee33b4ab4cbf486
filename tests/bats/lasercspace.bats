#!/usr/bin/env bats
# lasercspace (manual 7.22) served by player-serve on a laser replayed from a
# real robot's log: every beam comes out shortened by at least the radius,
# with the source scan's timestamp and geometry.

load helpers

teardown() {
  kill_left_running "${server_pid:-}"
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
