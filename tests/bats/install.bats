#!/usr/bin/env bats
# cmake --install into a temporary prefix (never system-wide, no root), then
# what a newcomer does with it: run the installed tools, read their man pages,
# complete their subcommands, and build a C++ and a C client (tests/install/)
# against the prefix, once with find_package and once with pkg-config, that
# talk to the installed player-serve on a free loopback port.

load helpers

setup_file() {
  prefix="$BATS_FILE_TMPDIR/prefix"
  cmake --install "$build_dir" --prefix "$prefix" > "$BATS_FILE_TMPDIR/install.log"
}

setup() {
  prefix="$BATS_FILE_TMPDIR/prefix"
  # An instrumented build (scripts/test --sanitize) installs instrumented
  # static libraries: a client linking them needs the sanitizer runtimes.
  sanitize_flags="${PLAYERKIT_SANITIZE_FLAGS:-}"
  player_serve="$prefix/bin/player-serve"
  # Three position samples 0.2 s apart; autorewind keeps them coming.
  log="$BATS_TEST_TMPDIR/run.log"
  cat > "$log" <<'LOG'
## Player version 1.5 
## File version 0.0.0 
1000.000 robot 6665 position 00 999.950 +0.100 +0.200 +1.571 +0.000 +0.000 +0.000 0
1000.200 robot 6665 position 00 1000.150 +0.300 +0.200 +1.571 +0.000 +0.000 +0.000 0
1000.400 robot 6665 position 00 1000.350 +0.500 +0.200 +1.571 +0.000 +0.000 +0.000 0
LOG
  cfg="$BATS_TEST_TMPDIR/robot.cfg"
  printf 'mcom:0 ( driver "lifomcom" )\nposition:0 ( driver "readlog" autorewind 1 )\n' > "$cfg"
}

teardown() {
  kill_left_running "${server_pid:-}"
}

# The pkg-config directory (lib/pkgconfig, or lib/<multiarch>/pkgconfig).
pkgconfig_dir() {
  dirname "$(find "$prefix" -name playerkit-client.pc -print -quit)"
}

# check_clients DIR: runs DIR/devices_cpp and DIR/devices_c against the
# installed player-serve and checks what they print.
check_clients() {
  start_server "$BATS_TEST_TMPDIR/serve.err" -p 0 --bind 127.0.0.1 -r "$log" "$cfg"
  run --separate-stderr timeout 20 "$1/devices_cpp" 127.0.0.1 "$server_port"
  echo "devices_cpp: $output $stderr"
  [ "$status" -eq 0 ]
  [[ "$output" == *"device mcom:0 lifomcom"* ]]
  [[ "$output" == *"device position:0 readlog"* ]]
  [[ "$output" =~ position:0\ x=0\.[135]00\ y=0\.200 ]]
  run --separate-stderr timeout 20 "$1/devices_c" 127.0.0.1 "$server_port"
  echo "devices_c: $output $stderr"
  [ "$status" -eq 0 ]
  [[ "$output" == *"device 26:0"* ]]  # mcom
  [[ "$output" == *"device 4:0"* ]]   # position
  [[ "$output" =~ position:0\ xpos=[135]00\ ypos=200 ]]
}

@test "the install has the tools, libraries, headers, CMake package and pkg-config files" {
  for tool in player-serve player-cat player-send player-log amcl-offline; do
    [ -x "$prefix/bin/$tool" ]
  done
  [ -n "$(find "$prefix" -name libplayerkit_client.a)" ]
  [ -n "$(find "$prefix" -name libplayerkit_playercclient.a)" ]
  [ -n "$(find "$prefix" -name libplayerkit_protocol.a)" ]
  [ -f "$prefix/include/playerkit/client/client.hpp" ]
  [ -f "$prefix/include/playerkit/client/typed/laser.hpp" ]
  [ -f "$prefix/include/playerkit/client/c/playercclient.h" ]
  [ -f "$prefix/include/playerkit/protocol/messages/laser.hpp" ]
  # Test helpers stay in the source tree.
  [ -z "$(find "$prefix/include" -name '*_test*')" ]
  [ -n "$(find "$prefix" -path '*/cmake/playerkit/playerkitConfig.cmake')" ]
  [ -f "$(pkgconfig_dir)/playercclient.pc" ]
  # Nothing installed points back into the source or build tree.
  run grep -rlIF -e "$repo_root/lib" -e "$build_dir" "$prefix/lib" "$prefix/include"
  [ "$status" -eq 1 ]
}

@test "every installed tool answers --version with its name and playerkit's" {
  local tool
  for path in "$prefix"/bin/*; do
    tool=$(basename "$path")
    run "$path" --version
    echo "$tool: $output"
    [ "$status" -eq 0 ]
    [[ "$output" == "$tool (playerkit) "* ]]
  done
}

@test "every installed tool has a man page from its --help, naming its subcommands" {
  local tool
  for path in "$prefix"/bin/*; do
    tool=$(basename "$path")
    page="$prefix/share/man/man1/$tool.1.gz"
    [ -f "$page" ]
    grep -qF ".TH $(tr a-z A-Z <<< "$tool" | sed 's/-/\\-/g') 1" <(zcat "$page")
    # Each long option of the --help is in the page (hyphens escaped for roff).
    for option in $("$path" --help | grep -oE '^  (-[^-, ]+,)?--[a-z][a-z-]*' | sed 's/.*--/--/'); do
      zgrep -qF -- "$(sed 's/-/\\-/g' <<< "$option")" "$page" || { echo "$tool.1 lacks $option"; return 1; }
    done
  done
  for sub in info convert cut record replay; do
    zgrep -q "^\.SS player\\\\-log $sub$" "$prefix/share/man/man1/player-log.1.gz"
  done
  for sub in map perturb localize eval; do
    zgrep -q "^\.SS amcl\\\\-offline $sub$" "$prefix/share/man/man1/amcl-offline.1.gz"
  done
  zgrep -q 'DEVICE cmd FIELD=VALUE' "$prefix/share/man/man1/player-send.1.gz"
  zgrep -q 'DEVICE req NAME' "$prefix/share/man/man1/player-send.1.gz"
  if command -v man > /dev/null; then
    run env MANWIDTH=80 man -l "$prefix/share/man/man1/player-serve.1.gz"
    [ "$status" -eq 0 ]
    [[ "$output" =~ player-serve\ +-\ +serve\ +the\ +devices ]]
    [[ "$output" == *"-p, --port UINT=6665"* ]]
  fi
}

# complete WORDS...: what the installed completion offers for the last word.
complete_words() {
  local tool="$1" script="$prefix/share/bash-completion/completions/$1"
  # shellcheck source=/dev/null
  source "$script"
  local function
  function=$(complete -p "$tool" | sed -n 's/.*-F \([^ ]*\) .*/\1/p')
  COMP_WORDS=("$@")
  COMP_CWORD=$((${#COMP_WORDS[@]} - 1))
  COMPREPLY=()
  "$function"
  echo "${COMPREPLY[*]}"
}

@test "bash completion offers each tool's subcommands and long options" {
  for path in "$prefix"/bin/*; do
    [ -f "$prefix/share/bash-completion/completions/$(basename "$path")" ]
  done
  [ "$(complete_words player-log re)" = "record replay" ]
  [ "$(complete_words player-log '')" = "info convert cut record replay" ]
  [ "$(complete_words player-log replay --b)" = "--bind --burst" ]
  [ "$(complete_words amcl-offline localize --init)" = "--init-pose --init-var" ]
  [ "$(complete_words amcl-offline l)" = "localize" ]
  [ "$(complete_words player-send mcom:0 '')" = "cmd req" ]
  [ "$(complete_words player-send mcom:0 req '')" = "" ]
  [ "$(complete_words player-cat laser --fo)" = "--format" ]
  [ "$(complete_words player-serve --rea)" = "--readlog --readlogspeed" ]
}

@test "find_package(playerkit): a C++ and a C client built against the prefix talk to player-serve" {
  cmake -S "$repo_root/tests/install" -B "$BATS_TEST_TMPDIR/build" \
    -DCMAKE_PREFIX_PATH="$prefix" -DCMAKE_CXX_FLAGS="$sanitize_flags" -DCMAKE_C_FLAGS="$sanitize_flags" \
    > "$BATS_TEST_TMPDIR/configure.log" 2>&1 \
    || { cat "$BATS_TEST_TMPDIR/configure.log"; return 1; }
  cmake --build "$BATS_TEST_TMPDIR/build" -j 2 > "$BATS_TEST_TMPDIR/build.log" 2>&1 \
    || { cat "$BATS_TEST_TMPDIR/build.log"; return 1; }
  check_clients "$BATS_TEST_TMPDIR/build"
}

@test "pkg-config playerkit-client and playercclient: the same clients, built by hand" {
  export PKG_CONFIG_PATH
  PKG_CONFIG_PATH="$(pkgconfig_dir)"
  [ "$(pkg-config --variable=prefix playerkit-client)" = "$prefix" ]
  out="$BATS_TEST_TMPDIR/bin"
  mkdir -p "$out"
  # shellcheck disable=SC2046,SC2086 # pkg-config's output and sanitize_flags are lists of flags
  "${CXX:-c++}" -std=c++20 $sanitize_flags -o "$out/devices_cpp" "$repo_root/tests/install/devices.cpp" \
    $(pkg-config --cflags --libs playerkit-client)
  # 1.5 programs say #include <playercclient.h>; a plain C compiler and linker.
  # shellcheck disable=SC2046,SC2086
  "${CC:-cc}" $sanitize_flags -o "$out/devices_c" "$repo_root/tests/install/devices.c" \
    $(pkg-config --cflags --libs playercclient)
  check_clients "$out"
}
