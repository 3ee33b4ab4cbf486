# Shared setup for the command-line tests. PLAYERKIT_BUILD_DIR points at the build
# tree (scripts/test sets it); by default ./build at the top of the repository.
repo_root="$(cd "$(dirname "${BATS_TEST_FILENAME}")/../.." && pwd)"
build_dir="${PLAYERKIT_BUILD_DIR:-$repo_root/build}"
player_serve="$build_dir/tools/player-serve/player-serve"
player_cat="$build_dir/tools/player-cat/player-cat"
player_view="$build_dir/tools/player-view/player-view"
player_send="$build_dir/tools/player-send/player-send"
player_log="$build_dir/tools/player-log/player-log"
player_drivers="$build_dir/tools/drivers/player-drivers"
amcl_offline="$build_dir/tools/amcl-offline/amcl-offline"
wire_roundtrip="$build_dir/examples/wire-roundtrip/wire-roundtrip"
bats_require_minimum_version 1.5.0
battery_plugin="$build_dir/examples/plugin-driver/libplayerkit_battery_plugin.so"

# Waits with a deadline (PLAYERKIT_WAIT_TIMEOUT seconds, default 30) that end
# early when the process waited on has died, and say what they waited for:
# wait_until, wait_for_file, wait_for_nonempty, wait_for_line, wait_for_lines,
# wait_for_port, wait_for_exit (sets exit_status), read_bytes.
wait_name=bats
# shellcheck source=scripts/lib/wait.bash
source "$repo_root/scripts/lib/wait.bash"

# start_server LOGFILE ARGS...: runs player-serve in the background with its
# stderr in LOGFILE; sets server_pid, and server_port from the first
# "listening on port N" line (waits PLAYERKIT_WAIT_TIMEOUT, 30 s, for it: a
# replay indexes its whole log first, 6 s for a Radish log under
# AddressSanitizer on an idle machine; a server that exits early is noticed at
# once).
start_server() {
  local log="$1"
  shift
  start_daemon "$log" "$player_serve" "$@"
}

# start_replay LOGFILE ARGS...: the same for `player-log replay ARGS...`.
start_replay() {
  local log="$1"
  shift
  start_daemon "$log" "$player_log" replay "$@"
}

start_daemon() {
  local log="$1"
  shift
  # Emptied first: the background shell truncates LOG only once it runs, and
  # a loaded machine may run it after the wait has read a line left there by
  # an earlier server (a test serving twice with one LOG).
  : >"$log"
  "$@" 2>"$log" &
  server_pid=$!
  server_port=""
  wait_for_line --pid "$server_pid" "$log" 'listening on port [0-9]+' || return 1
  server_port="$(sed -n 's/.*listening on port \([0-9][0-9]*\).*/\1/p' "$log" | head -n 1)"
}

# kill_left_running PID...: a test's teardown; kills whatever of these is
# still running (empty arguments are skipped), so a failed test leaves no
# server behind to hold a port or the next test's files.
kill_left_running() {
  local pid
  for pid in "$@"; do
    if [ -n "$pid" ] && kill -0 "$pid" 2>/dev/null; then
      kill -KILL "$pid"
      wait "$pid" 2>/dev/null || true
    fi
  done
}

# start_emulator OUT ERR ARGS...: `player-drivers emulate ARGS...` in the
# background (emulator_pid); waits (PLAYERKIT_WAIT_TIMEOUT, 30 s) for its
# stdout to name every emulated device: one line for each --link or --tcp.
start_emulator() {
  local out="$1" err="$2"
  shift 2
  : >"$out"  # no lines of an earlier emulator (see start_daemon)
  "$player_drivers" emulate "$@" >"$out" 2>"$err" &
  emulator_pid=$!
  local wanted=0 word
  for word in "$@"; do
    case "$word" in --link | --tcp) wanted=$((wanted + 1)) ;; esac
  done
  wait_for_lines --pid "$emulator_pid" --log "$out" --log "$err" "$out" "$wanted"
}

# run_until WHAT FILTER COMMANDS ARGS...: `player-drivers run ARGS... --stdin
# --format json` in the background (run_pid), COMMANDS (JSON lines, one
# string) on its stdin, which stays open until a reading matches the jq
# FILTER (e.g. 'select(.data.xspeed == 100)'; WHAT names it in the message)
# within PLAYERKIT_WAIT_TIMEOUT: a loaded machine may take seconds where a
# fixed count of readings would end too soon. Then stdin is closed, which
# ends the run, and its exit status must be 0. The readings are in
# $readings, its stderr in $run_err.
run_until() {
  local what=$1 filter=$2 commands=$3
  shift 3
  readings="$BATS_TEST_TMPDIR/readings.json"
  run_err="$BATS_TEST_TMPDIR/run.err"
  local fifo="$BATS_TEST_TMPDIR/commands.fifo"
  rm -f "$fifo"
  mkfifo "$fifo"
  "$player_drivers" run "$@" --stdin --format json <"$fifo" >"$readings" 2>"$run_err" &
  run_pid=$!
  exec 4>"$fifo"
  printf '%s\n' "$commands" >&4
  _run_until_matched() { [ "$(jq -s "[.[] | $filter] | length" "$readings" 2>/dev/null)" -gt 0 ]; }
  if ! wait_until --pid "$run_pid" --log "$run_err" "$what" _run_until_matched; then
    exec 4>&-
    return 1
  fi
  exec 4>&-
  wait_for_exit "$run_pid"
  [ "$exit_status" -eq 0 ]
}

# stop_cleanly PID: SIGTERM, then the exit status must be 0 (within PLAYERKIT_WAIT_TIMEOUT).
stop_cleanly() {
  kill -TERM "$1"
  wait_for_exit "$1"
  [ "$exit_status" -eq 0 ]
}
