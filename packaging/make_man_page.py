#!/usr/bin/env python3
"""Writes a section 1 man page for a playerkit tool from its --help text (and
its subcommands' --help), so the page says exactly what the program says.

    make_man_page.py PROGRAM --version 0.1.0 -o player-cat.1
"""

import argparse
import re
import sys

import cli_help

# A footer line "Label: ..." or "Label:" (one to three words) starts a section,
# and so does a paragraph's first line that is a capitalised heading ("Commands
# (cmd) and requests (req) by interface:").
_SECTION_LABEL = re.compile(r"^([A-Z][a-z]+(?: [a-z]+){0,2}):(?: (.*))?$")
_SECTION_HEADING = re.compile(r"^([A-Z][^:]{0,70}):$")


def roff(text):
    """Escapes text for roff: backslashes, hyphens (so options copy as typed),
    and a leading dot or quote that roff would read as a request."""
    text = text.replace("\\", "\\e").replace("-", "\\-")
    if text.startswith((".", "'")):
        text = "\\&" + text
    return text


def _entry_item(entry):
    if entry.is_option:
        names = ", ".join(f"\\fB{roff(n)}\\fR" for n in entry.names)
    else:
        names = f"\\fI{roff(entry.names[0])}\\fR"
    argument = f" \\fI{roff(entry.argument)}\\fR" if entry.argument else ""
    return [".TP", names + argument, roff(entry.text) if entry.text else "\\&"]


def _groups(page):
    out = []
    for group, entries in page.groups.items():
        if group == "Subcommands":
            continue
        if group != "Options":
            title = "Arguments" if group == "Positionals" else group
            out += [".PP", f"\\fB{roff(title)}:\\fR"]
        for entry in entries:
            out += _entry_item(entry)
    return out


def _paragraphs(lines):
    paragraph = []
    for line in lines:
        if line.strip():
            paragraph.append(line)
        elif paragraph:
            yield paragraph
            paragraph = []
    if paragraph:
        yield paragraph


def _text_block(paragraph):
    """A paragraph with indented lines (examples, tables) keeps its layout;
    plain prose is left to roff to fill."""
    if any(line.startswith(" ") for line in paragraph):
        return [".PP", ".nf"] + [roff(line) for line in paragraph] + [".fi"]
    return [".PP"] + [roff(line) for line in paragraph]


def _footer_sections(footer):
    """Splits the tool's free-text footer into man sections at "Label:" lines
    (EXAMPLES, EXIT STATUS, ...); text before the first label is NOTES."""
    sections = []  # [title, [lines]]
    for paragraph in _paragraphs(footer):
        preformatted = any(line.startswith(" ") for line in paragraph)
        current = []
        for number, line in enumerate(paragraph):
            label = _SECTION_LABEL.match(line) or (number == 0 and _SECTION_HEADING.match(line))
            # Inside a laid-out block only the first line may start a section.
            if label and (number == 0 or not preformatted):
                if current:
                    sections[-1][1].append(current)
                sections.append([label.group(1).upper(), []])
                rest = label.group(2) if label.re is _SECTION_LABEL else None
                current = [rest] if rest else []
            else:
                if not sections:
                    sections.append(["NOTES", []])
                current.append(line)
        if current:
            sections[-1][1].append(current)
    out = []
    for title, paragraphs in sections:
        out.append(f".SH {roff(title)}")
        for paragraph in paragraphs:
            out += _text_block(paragraph)
    return out


def _name_line(page):
    """The one-line summary: the description's first sentence group, without
    the "player-cat [HOST[:PORT]] DEVICE...:" prefix some tools start with."""
    first = []
    for line in page.description:
        if not line.strip() or line.startswith(" "):
            break
        first.append(line.strip())
    summary = " ".join(first)
    tool = page.name.split()[0]
    if summary.startswith(tool) and ": " in summary:
        summary = summary.split(": ", 1)[1]
    return summary.rstrip(".") or tool


def _description(page):
    lines = [line for line in page.description
             if line.strip() not in page.synopsis_lines()]
    if lines and lines[0].startswith(page.name.split()[0]) and ": " in lines[0]:
        lines[0] = lines[0].split(": ", 1)[1]
    if lines:
        lines[0] = lines[0][:1].upper() + lines[0][1:]
    return lines


def man_page(page, version):
    tool = page.name
    out = [
        f'.\\" Generated from `{tool} --help` by packaging/make_man_page.py; do not edit.',
        f'.TH {roff(tool.upper())} 1 "" "playerkit {version}" "User Commands"',
        ".SH NAME",
        f"{roff(tool)} \\- {roff(_name_line(page))}",
        ".SH SYNOPSIS",
    ]
    forms = [page.usage] + page.synopsis_lines() + [sub.usage for sub in page.subcommands]
    for number, form in enumerate(forms):
        if number:
            out.append(".br")
        command, _, rest = form.partition(" ")
        out.append(f"\\fB{roff(command)}\\fR {roff(rest)}")
    out.append(".SH DESCRIPTION")
    for paragraph in _paragraphs(_description(page)):
        out += _text_block(paragraph)
    if _groups(page):
        out += [".SH OPTIONS"] + _groups(page)
    if page.subcommands:
        out.append(".SH SUBCOMMANDS")
        for sub in page.subcommands:
            out += [f".SS {roff(sub.name)}", roff(" ".join(l.strip() for l in sub.description if l.strip())),
                    ".PP", f"\\fB{roff(sub.name)}\\fR {roff(sub.usage[len(sub.name):].strip())}"]
            out += _groups(sub)
    out += _footer_sections(page.footer)
    out += [".SH SEE ALSO"]
    return "\n".join(out) + "\n"


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("program", help="the built tool to run with --help")
    parser.add_argument("--version", required=True, help="playerkit's version, for the page footer")
    parser.add_argument("--see-also", default="", help="other tools, comma separated")
    parser.add_argument("-o", "--output", required=True)
    args = parser.parse_args()
    try:
        page = cli_help.read_tool(args.program)
    except (RuntimeError, ValueError, OSError) as error:
        print(f"make_man_page: {error}", file=sys.stderr)
        return 1
    text = man_page(page, args.version)
    others = [name for name in args.see_also.split(",") if name and name != page.name]
    see_also = ",\n".join(f"\\fB{roff(name)}\\fR(1)" for name in others) or "playerkit's README.md"
    with open(args.output, "w", encoding="utf-8") as output:
        output.write(text + see_also + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
