#!/usr/bin/env bats
# The cmucam2 family through player-drivers and player-serve: a CMUcam2
# emulated on a pseudo-terminal (a synthetic scene, or an image), probed,
# run, traced, and served from data/config with its servos moved by a
# client. Every wait is bounded; devices sit in $BATS_TEST_TMPDIR.

load helpers

teardown() {
  kill_left_running "${emulator_pid:-}" "${server_pid:-}"
}

@test "a CMUcam2: emulate, probe, run the blobs of a colour as JSON" {
  cam="$BATS_TEST_TMPDIR/cam"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" cmucam2 --link "$cam"
  grep -qx "cmucam2 on $cam: blobfinder:0 ( driver \"cmucam2\" port \"$cam\" )" "$BATS_TEST_TMPDIR/emulate.out"

  run --separate-stderr timeout 60 "$player_drivers" probe "$cam"
  [ "$status" -eq 0 ]
  [[ "$output" == *"$cam: cmucam2 at 115200 baud, CMUcam2 v1.00 c6"* ]]
  [[ "$output" == *"    blobfinder:0 ( driver \"cmucam2\" port \"$cam\" )"* ]]

  # The red disc of the synthetic scene, 10 degrees left of centre.
  run --separate-stderr timeout 60 "$player_drivers" run cmucam2 "port=$cam" "color0=[200 240 16 60 16 60]" \
    -n 2 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -s 'length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[1].data.blobs | length' <<<"$output")" -eq 1 ]
  x="$(jq -s -r '.[1].data.blobs[0].x' <<<"$output")"
  [ "$x" -ge 25 ] && [ "$x" -le 27 ]
  [ "$(jq -s -r '.[1].data.blobs[0].color' <<<"$output")" -eq $((0xdc2626)) ]
  stop_cleanly "$emulator_pid"
}

@test "a CMUcam2: --trace shows the commands and the T packets a line each" {
  cam="$BATS_TEST_TMPDIR/cam"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" cmucam2 --link "$cam"
  run --separate-stderr timeout 60 "$player_drivers" run cmucam2 "port=$cam" "color0=[200 240 16 60 16 60]" -n 2 --trace
  [ "$status" -eq 0 ]
  [[ "$stderr" == *"> 50 4D 20 31 0D"* ]]                                     # PM 1
  [[ "$stderr" == *"> 54 43 20 32 30 30 20 32 34 30 20 31 36 20 36 30 20 31 36 20 36 30 0D"* ]]  # TC 200 240 16 60 16 60
  [[ "$stderr" == *"< 54 20 32 36 20 37 32 "* ]]                              # T 26 72 ...
  [[ "$stderr" == *"> 0D"$'\n'* ]]                                            # the lone CR, a command of its own
  [[ "$stderr" != *"not a telegram"* ]]
  stop_cleanly "$emulator_pid"
}

@test "a CMUcam2 looking at an image finds its coloured square" {
  cam="$BATS_TEST_TMPDIR/cam"
  image="$BATS_TEST_TMPDIR/scene.ppm"
  # 88 x 143 grey, a blue square at columns 60-69, rows 20-29 (plain PPM).
  {
    printf 'P3\n88 143\n255\n'
    for y in $(seq 0 142); do
      for x in $(seq 0 87); do
        if [ "$x" -ge 60 ] && [ "$x" -lt 70 ] && [ "$y" -ge 20 ] && [ "$y" -lt 30 ]; then
          printf '20 20 220 '
        else
          printf '10 10 10 '
        fi
      done
      printf '\n'
    done
  } >"$image"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" cmucam2 --link "$cam" "image=$image"
  run --separate-stderr timeout 60 "$player_drivers" run cmucam2 "port=$cam" "color0=[0 40 0 40 200 240]" \
    -n 1 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -r '.data.blobs[0] | "\(.x) \(.y) \(.left) \(.right) \(.top) \(.bottom)"' <<<"$output")" = "65 25 61 70 21 30" ]
  stop_cleanly "$emulator_pid"
}

@test "data/config/cmucam2.cfg serves the emulated camera and its servos" {
  cam="$BATS_TEST_TMPDIR/cam"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" cmucam2 --link "$cam"
  sed "s|\"/tmp/cmucam2\"|\"$cam\"|" "$repo_root/data/config/cmucam2.cfg" >"$BATS_TEST_TMPDIR/cmucam2.cfg"
  [ "$(grep -c "devicepath \"$cam\"" "$BATS_TEST_TMPDIR/cmucam2.cfg")" -eq 2 ]
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 "$BATS_TEST_TMPDIR/cmucam2.cfg"
  # Both devices in one client: the camera's link opens once (a second
  # client after the first left would have the link closed and reopened,
  # slow under the sanitizer); --timeout for the camera's start-up on a
  # loaded machine.
  run --separate-stderr timeout 60 "$player_cat" "localhost:$server_port" blobfinder:0 ptz:0 --once --format json --timeout 30
  [ "$status" -eq 0 ]
  [ "$(jq -s -r '.[] | select(.device == "blobfinder") | .data.blobs | length' <<<"$output")" -eq 2 ]
  [ "$(jq -s -r '.[] | select(.device == "ptz") | .data.pan' <<<"$output")" -eq 0 ]
  stop_cleanly "$server_pid"
  stop_cleanly "$emulator_pid"
}

@test "a CMUcam2's servos: run cmucam2_ptz, a request, and info lists the options" {
  cam="$BATS_TEST_TMPDIR/cam"
  start_emulator "$BATS_TEST_TMPDIR/emulate.out" "$BATS_TEST_TMPDIR/emulate.err" cmucam2 --link "$cam"
  run --separate-stderr timeout 60 "$player_drivers" run cmucam2_ptz "port=$cam" -n 1 --format json
  [ "$status" -eq 0 ]
  [ "$(jq -r '.device' <<<"$output")" = ptz ]
  [ "$(jq -r '"\(.data.pan) \(.data.tilt) \(.data.zoom)"' <<<"$output")" = "0 0 48" ]

  run --separate-stderr timeout 60 "$player_drivers" run cmucam2_ptz "port=$cam" --req control-mode mode=1
  [ "$status" -eq 0 ]
  [ "$(jq -r '.type' <<<"$output")" = ack ]

  run --separate-stderr "$player_drivers" info cmucam2
  [ "$status" -eq 0 ]
  [[ "$output" == *"devicepath"* ]]
  [[ "$output" == *"color9"* ]]
  [[ "$output" == *"num_blobs"* ]]
  stop_cleanly "$emulator_pid"
}
