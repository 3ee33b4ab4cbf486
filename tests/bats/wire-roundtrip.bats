#!/usr/bin/env bats
# examples/wire-roundtrip: JSON -> Player wire bytes -> JSON.

load helpers

@test "a real laser scan survives the round trip exactly" {
  run --separate-stderr "$wire_roundtrip" "$repo_root/data/messages/intel-lab-first-scan.json"
  [ "$status" -eq 0 ]
  [[ "$stderr" == "laser:0 data: 1245 bytes on the wire (32 header + 1213 payload)" ]]
  printf '%s' "$output" > "$BATS_TEST_TMPDIR/out.json"
  python3 - "$repo_root/data/messages/intel-lab-first-scan.json" "$BATS_TEST_TMPDIR/out.json" <<'PY'
import json, sys
want, got = (json.load(open(p)) for p in sys.argv[1:3])
assert got == want, (got, want)
PY
}

@test "--hex prints the header bytes of the spec's layout" {
  run --separate-stderr "$wire_roundtrip" --hex - <<<'{"type":"cmd","device":"position","index":1,"time":1086000000.25,"data":{"xspeed":200}}'
  [ "$status" -eq 0 ]
  # stx 5878, type 2 (cmd), device 4 (position), index 1, time 1086000000 s 250000 us
  [[ "$stderr" == *"58 78 00 02 00 04 00 01 40 bb 0b 80 00 03 d0 90"* ]]
  # payload: xspeed (offset 12) = 200 = 0x000000c8
  [[ "$stderr" == *"00 00 00 00 00 00 00 00 00 00 00 00 00 00 00 c8"* ]]
}

@test "bad input names the line and the field, exit 2" {
  run "$wire_roundtrip" - <<<$'{"type":"cmd","device":"position","data":{}}\n{"type":"cmd","device":"position","data":{"xspeed":"fast"}}'
  [ "$status" -eq 2 ]
  [[ "$output" == *"-:2: player_position_cmd_t.xspeed: expected an integer"* ]]
}
