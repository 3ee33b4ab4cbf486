"""Reads a tool's --help (CLI11's layout) into a structure that the man page
and bash completion generators share, so both always match the program.

CLI11 prints: a description, a "Usage:" line, then groups ("Positionals:",
"Options:", "Subcommands:", or a named option group), each entry as two
spaces, a name column and a description; then the footer the tool set
(free text: examples, formats, exit status). Subcommands print the same for
themselves, followed by the parent's footer again.
"""

import dataclasses
import os
import re
import subprocess

_GROUP_HEADING = re.compile(r"^([A-Z][A-Za-z ]*):$")
# Two spaces, a name column, then at least two spaces before the description.
_ENTRY = re.compile(r"^  (\S.*?)(?:\s{2,}(\S.*))?$")
_KNOWN_GROUPS = ("Positionals", "Options", "Subcommands")


@dataclasses.dataclass
class Entry:
    """One line of a CLI11 group: an option, a positional or a subcommand."""

    names: list  # "-p", "--port"; or the positional's or subcommand's name
    argument: str  # "UINT=6665", "TEXT REQUIRED", or ""
    text: str

    @property
    def is_option(self):
        return self.names[0].startswith("-")


@dataclasses.dataclass
class HelpPage:
    """One program's (or subcommand's) help, split into its parts."""

    name: str  # "player-log" or "player-log record"
    description: list  # lines before "Usage:"
    usage: str  # with the program's path replaced by `name`
    groups: dict  # group heading -> [Entry]
    footer: list  # lines after the last group
    subcommands: list = dataclasses.field(default_factory=list)  # [HelpPage]

    def entries(self, group):
        return self.groups.get(group, [])

    def options(self):
        return [e for entries in self.groups.values() for e in entries if e.is_option]

    def long_options(self):
        return [n for e in self.options() for n in e.names if n.startswith("--")]

    def short_options(self):
        return [n for e in self.options() for n in e.names if re.fullmatch(r"-[^-]", n)]

    def synopsis_lines(self):
        """The description's own indented usage forms ("  player-send ... cmd ..."),
        which tools whose subcommands are positional words print."""
        tool = self.name.split()[0]
        return [line.strip() for line in self.description
                if line.startswith(" ") and line.strip().startswith(tool + " ")]

    def keywords(self):
        """Literal lowercase words of the synopsis forms after the tool name,
        e.g. cmd and req of `player-send DEVICE cmd FIELD=VALUE...`."""
        words = []
        for form in self.synopsis_lines():
            for word in form.split()[1:]:
                if re.fullmatch(r"[a-z][a-z0-9-]*", word) and word not in words:
                    words.append(word)
        return words


    def words_before_keywords(self):
        """How many words at least precede a keyword: player-send's forms put
        one (DEVICE; [HOST[:PORT]] is optional) before cmd and req."""
        counts = []
        for form in self.synopsis_lines():
            required = 0
            for word in form.split()[1:]:
                if word in self.keywords():
                    counts.append(required)
                    break
                if not word.startswith(("[", "-")):
                    required += 1
        return min(counts, default=0)


def _parse_entry(line):
    match = _ENTRY.match(line)
    if not match:
        return None
    left, text = match.group(1), match.group(2) or ""
    head, _, argument = left.partition(" ")
    names = head.split(",") if head.startswith("-") else [head]
    return Entry(names=names, argument=argument.strip(), text=text)


def parse(text, name):
    """Splits CLI11 help text into a HelpPage. `name` replaces the program path
    that CLI11 prints after "Usage:"."""
    lines = text.rstrip("\n").split("\n")
    index = 0
    description = []
    while index < len(lines) and not lines[index].startswith("Usage:"):
        description.append(lines[index].rstrip())
        index += 1
    if index == len(lines):
        # Not CLI11's layout: the whole text describes the program.
        return HelpPage(name=name, description=description, usage=f"{name} [OPTIONS]",
                        groups={}, footer=[])
    usage_words = lines[index][len("Usage:"):].split()
    depth = len(name.split())
    usage = " ".join(name.split() + usage_words[depth:])
    index += 1

    groups = {}
    while True:
        while index < len(lines) and not lines[index].strip():
            index += 1
        if index == len(lines):
            break
        heading = _GROUP_HEADING.match(lines[index])
        if not heading:
            break
        block = []
        cursor = index + 1
        while cursor < len(lines) and lines[cursor].startswith("  "):
            block.append(lines[cursor])
            cursor += 1
        entries = []
        for line in block:
            if line.startswith("    ") and entries:  # a wrapped description
                entries[-1].text += " " + line.strip()
                continue
            entry = _parse_entry(line)
            if entry:
                entries.append(entry)
        group = heading.group(1)
        # A footer section such as "Examples:" looks like a group; CLI11's own
        # groups are the known ones, or option groups (every entry an option).
        if not entries or (group not in _KNOWN_GROUPS and not all(e.is_option for e in entries)):
            break
        groups[group] = entries
        index = cursor

    footer = [line.rstrip() for line in lines[index:]]
    while footer and not footer[-1]:
        footer.pop()
    return HelpPage(name=name, description=description, usage=usage, groups=groups, footer=footer)


def run_help(program, args):
    """The --help text of `program args...`. The program runs from its own
    directory's name on PATH so that CLI11 prints the bare name in "Usage:"."""
    env = dict(os.environ)
    directory, base = os.path.split(os.path.abspath(program))
    env["PATH"] = directory + os.pathsep + env.get("PATH", "")
    result = subprocess.run([base, *args, "--help"], env=env, capture_output=True,
                            text=True, timeout=60, check=False)
    if result.returncode != 0:
        raise RuntimeError(f"{base} {' '.join(args)} --help exited {result.returncode}: {result.stderr}")
    return result.stdout


def read_tool(program, name=None):
    """The HelpPage of a tool and of each of its subcommands."""
    name = name or os.path.basename(program)
    page = parse(run_help(program, []), name)
    for entry in page.entries("Subcommands"):
        sub = entry.names[0]
        page.subcommands.append(parse(run_help(program, [sub]), f"{name} {sub}"))
    return page
