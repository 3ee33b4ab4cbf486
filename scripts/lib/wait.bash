# Waits with a deadline, for scripts that start programs in the background and
# must not assume a fast machine. Sourced (not run) by scripts/demo and
# tests/bats/helpers.bash; needs bash 5 (EPOCHREALTIME).
#
# Every wait polls its condition every PLAYERKIT_WAIT_INTERVAL seconds
# (default 0.05) until it holds or PLAYERKIT_WAIT_TIMEOUT seconds (default 30,
# fractions allowed) have passed. Given --pid PID, it stops at once when that
# process has ended (a server that died will never write its port). When it
# gives up it says on stderr what it waited for, why it stopped, and shows each
# --log FILE, then returns 1.
#
#   wait_until [--pid PID] [--log FILE]... [--timeout S] WHAT COMMAND [ARGS...]
#       until COMMAND succeeds; WHAT names the condition in the message
#   wait_for_file [OPTIONS] FILE             FILE exists
#   wait_for_nonempty [OPTIONS] FILE         FILE exists and is not empty
#   wait_for_line [OPTIONS] FILE REGEX       a line of FILE matches REGEX (grep -E)
#   wait_for_lines [OPTIONS] FILE N          FILE has at least N lines
#   wait_for_port [OPTIONS] HOST PORT        a TCP connection to HOST:PORT is accepted
#   wait_for_exit [OPTIONS] PID              PID has ended: sets exit_status; on the
#                                            deadline PID is killed (SIGKILL)
#   read_bytes [--log F] [--timeout S] FD N FILE WHAT     appends exactly N bytes read from file
#                                            descriptor FD to FILE, or fails when the
#                                            peer closes or the deadline passes first
# wait_for_line, wait_for_lines and wait_for_nonempty show FILE when they give
# up unless --log names other files. Messages start with "$wait_name: " (the
# script's name unless set).

wait_name=${wait_name:-${0##*/}}

# _wait_us SECONDS: SECONDS (e.g. 30, 0.5) in microseconds.
_wait_us() {
  local whole=${1%%.*} fraction=
  [[ $1 == *.* ]] && fraction=${1#*.}
  fraction="${fraction}000000"
  echo $(( 10#${whole:-0} * 1000000 + 10#${fraction:0:6} ))
}

# _wait_now: microseconds since the epoch (EPOCHREALTIME, whatever the locale's decimal point).
_wait_now() {
  echo "${EPOCHREALTIME//[!0-9]/}"
}

# _wait_give_up WHAT WHY LOG...: the message, with each log.
_wait_give_up() {
  local what=$1 why=$2 log
  shift 2
  {
    echo "$wait_name: gave up waiting for $what: $why"
    for log in "$@"; do
      if [ -f "$log" ]; then
        echo "--- $log:"
        cat "$log"
        echo "--- end of $log"
      else
        echo "--- $log does not exist"
      fi
    done
  } >&2
}

wait_until() {
  local pid="" timeout=${PLAYERKIT_WAIT_TIMEOUT:-30} logs=()
  while :; do
    case ${1:-} in
      --pid) pid=$2; shift 2 ;;
      --log) logs+=("$2"); shift 2 ;;
      --timeout) timeout=$2; shift 2 ;;
      *) break ;;
    esac
  done
  local what=$1
  shift
  local deadline status
  deadline=$(( $(_wait_now) + $(_wait_us "$timeout") ))
  while :; do
    "$@" && return 0
    if [ -n "$pid" ] && ! kill -0 "$pid" 2>/dev/null; then
      "$@" && return 0  # it may have come true just before the process ended
      status=0
      wait "$pid" 2>/dev/null || status=$?
      _wait_give_up "$what" "process $pid ended first (exit status $status)" "${logs[@]}"
      return 1
    fi
    if [ "$(_wait_now)" -ge "$deadline" ]; then
      "$@" && return 0
      _wait_give_up "$what" "timed out after ${timeout} s (PLAYERKIT_WAIT_TIMEOUT)" "${logs[@]}"
      return 1
    fi
    sleep "${PLAYERKIT_WAIT_INTERVAL:-0.05}"
  done
}

# The conditions, usable on their own too.
file_has_line() { grep -qE -- "$2" "$1" 2>/dev/null; }
file_has_lines() { [ -f "$1" ] && [ "$(wc -l <"$1")" -ge "$2" ]; }
port_accepts() { (exec 9<>"/dev/tcp/$1/$2") 2>/dev/null; }

# _wait_options ARGS...: splits leading options off into wait_options; the
# rest are in wait_args.
_wait_options() {
  wait_options=()
  while [[ ${1:-} == --* ]]; do
    wait_options+=("$1" "$2")
    shift 2
  done
  wait_args=("$@")
}

# _wait_has_log: wait_options has a --log.
_wait_has_log() {
  [[ " ${wait_options[*]} " == *" --log "* ]]
}

wait_for_file() {
  _wait_options "$@"
  wait_until "${wait_options[@]}" "${wait_args[0]} to exist" test -e "${wait_args[0]}"
}

wait_for_nonempty() {
  _wait_options "$@"
  _wait_has_log || wait_options+=(--log "${wait_args[0]}")
  wait_until "${wait_options[@]}" "${wait_args[0]} to be written" test -s "${wait_args[0]}"
}

wait_for_line() {
  _wait_options "$@"
  _wait_has_log || wait_options+=(--log "${wait_args[0]}")
  wait_until "${wait_options[@]}" "a line matching '${wait_args[1]}' in ${wait_args[0]}" \
    file_has_line "${wait_args[0]}" "${wait_args[1]}"
}

wait_for_lines() {
  _wait_options "$@"
  _wait_has_log || wait_options+=(--log "${wait_args[0]}")
  wait_until "${wait_options[@]}" "${wait_args[1]} lines in ${wait_args[0]}" \
    file_has_lines "${wait_args[0]}" "${wait_args[1]}"
}

wait_for_port() {
  _wait_options "$@"
  wait_until "${wait_options[@]}" "${wait_args[0]}:${wait_args[1]} to accept a connection" \
    port_accepts "${wait_args[0]}" "${wait_args[1]}"
}

_wait_ended() { ! kill -0 "$1" 2>/dev/null; }

wait_for_exit() {
  _wait_options "$@"
  local pid=${wait_args[0]}
  # shellcheck disable=SC2034 # exit_status is for the caller
  if wait_until "${wait_options[@]}" "process $pid to end" _wait_ended "$pid"; then
    # `|| ...` keeps a non-zero status from tripping errexit (set -e, bats).
    exit_status=0
    wait "$pid" 2>/dev/null || exit_status=$?
    return 0
  fi
  kill -KILL "$pid" 2>/dev/null || true
  return 1
}

read_bytes() {
  local timeout=${PLAYERKIT_WAIT_TIMEOUT:-30} logs=()
  while :; do
    case ${1:-} in
      --log) logs+=("$2"); shift 2 ;;
      --timeout) timeout=$2; shift 2 ;;
      *) break ;;
    esac
  done
  local fd=$1 count=$2 file=$3 what=$4 before after
  before=$(stat -c %s "$file" 2>/dev/null || echo 0)
  # head -c reads no more than it is asked for, even from a socket.
  timeout "$timeout" head -c "$count" <&"$fd" >>"$file" || true
  after=$(stat -c %s "$file")
  [ $((after - before)) -eq "$count" ] && return 0
  _wait_give_up "$what" "$((after - before)) of $count bytes came before the peer closed or ${timeout} s passed (PLAYERKIT_WAIT_TIMEOUT)" \
    "${logs[@]}"
  return 1
}
