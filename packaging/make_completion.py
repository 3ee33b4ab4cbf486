#!/usr/bin/env python3
"""Writes a bash completion script for a playerkit tool from its --help text:
its subcommands, the positional keywords of its usage forms (player-send's
cmd and req) and the long and short options of each, so completion follows
the program as it changes.

    make_completion.py PROGRAM -o player-log
"""

import argparse
import os
import re
import sys

import cli_help


def _words(names):
    return " ".join(dict.fromkeys(names))


def completion_script(page):
    tool = page.name
    function = "_playerkit_" + re.sub(r"[^A-Za-z0-9]", "_", tool)
    subcommands = [sub.name.split()[-1] for sub in page.subcommands]
    keywords = page.keywords()
    lines = [
        f"# bash completion for {tool}, generated from `{tool} --help` by",
        "# packaging/make_completion.py; do not edit.",
        f"{function}() {{",
        '  local cur="${COMP_WORDS[COMP_CWORD]}" sub=""',
    ]
    if subcommands:
        lines += [
            "  local i",
            '  for ((i = 1; i < COMP_CWORD; i++)); do',
            '    case "${COMP_WORDS[i]}" in',
            f'      {"|".join(subcommands)}) sub="${{COMP_WORDS[i]}}"; break ;;',
            "    esac",
            "  done",
        ]
    lines += ['  if [[ "$cur" == -* ]]; then', '    local options', '    case "$sub" in']
    for sub in page.subcommands:
        lines.append(f'      {sub.name.split()[-1]}) options="{_words(sub.long_options() + sub.short_options())}" ;;')
    lines += [
        f'      *) options="{_words(page.long_options() + page.short_options())}" ;;',
        "    esac",
        '    mapfile -t COMPREPLY < <(compgen -W "$options" -- "$cur")',
        "    return 0",
        "  fi",
    ]
    if subcommands:
        lines += [
            '  if [[ -z "$sub" ]]; then',
            f'    mapfile -t COMPREPLY < <(compgen -W "{_words(subcommands)}" -- "$cur")',
            "    return 0",
            "  fi",
        ]
    if keywords:
        # A keyword comes once, after the words its usage forms put first
        # (player-send: the device).
        lines += [
            "  local word",
            '  for word in "${COMP_WORDS[@]:1:COMP_CWORD-1}"; do',
            f'    case "$word" in {"|".join(keywords)}) return 0 ;; esac',
            "  done",
            f"  if ((COMP_CWORD > {page.words_before_keywords()})); then",
            f'    mapfile -t COMPREPLY < <(compgen -W "{_words(keywords)}" -- "$cur")',
            "  fi",
        ]
    # Nothing offered: -o default lets bash complete file names (logs, configs).
    lines += ["  return 0", "}", f"complete -o default -F {function} {tool}", ""]
    return "\n".join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("program", help="the built tool to run with --help")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    try:
        page = cli_help.read_tool(args.program)
    except (RuntimeError, ValueError, OSError) as error:
        print(f"make_completion: {error}", file=sys.stderr)
        return 1
    with open(args.output, "w", encoding="utf-8") as output:
        output.write(completion_script(page))
    return 0


if __name__ == "__main__":
    sys.exit(main())
