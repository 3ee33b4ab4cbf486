#!/usr/bin/env python3
"""Checks every #include "..." under lib/ against the layers drawn in
docs/architecture.md (the fenced block after the line `<!-- layers -->`).

Each line of that block is a layer, highest first. Its folders are the words
at the start of the line that begin with lib/ or tools/; the rest of the line
describes them. `lib/x/<name>` stands for every subfolder of lib/x that has no
line of its own, each one independent of the others; `lib/x/<name>/part`
for the folder `part` of each of them, and library code of one `<name>`
never includes another's, whatever their lines. A file of folder F may
include:
  * headers of F itself (F owns its subfolders unless they have lines of
    their own), and headers of folders on lower lines;
  * in test code (*_test.cpp, *test_support*, test_*.hpp) also folders on F's
    own line, and tests/support ("support/...").
Anything else is reported as file:line with both layers, and so is a folder of
lib/ with sources that the block does not place. Exit status 1 on any finding.

  check_layers.py [--root DIR]      # DIR: the source tree (default: this file's ../..)
"""

import argparse
import pathlib
import re
import sys

SOURCE_SUFFIXES = {".cpp", ".hpp", ".h", ".c", ".cc"}
INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
MARKER = "<!-- layers -->"


class LayerError(Exception):
    pass


def read_layer_lines(architecture: pathlib.Path):
    """[(line number, [folder or folder/<name>, ...]), ...], highest first."""
    lines = architecture.read_text(encoding="utf-8").splitlines()
    try:
        start = next(i for i, line in enumerate(lines) if line.strip() == MARKER)
    except StopIteration:
        raise LayerError(f"{architecture}: no line '{MARKER}' before the layer diagram")
    fence = start + 1
    while fence < len(lines) and not lines[fence].startswith("```"):
        fence += 1
    if fence == len(lines):
        raise LayerError(f"{architecture}:{start + 1}: no fenced block after '{MARKER}'")
    layers = []
    for number in range(fence + 1, len(lines)):
        line = lines[number]
        if line.startswith("```"):
            return layers
        folders = []
        for word in line.split():
            if not (word.startswith("lib/") or word.startswith("tools/")):
                break
            folders.append(word.rstrip("/"))
        if folders:
            layers.append((number + 1, folders))
    raise LayerError(f"{architecture}:{fence + 1}: the layer block is not closed")


def is_test_code(path: pathlib.Path) -> bool:
    name = path.name
    return (path.stem.endswith("_test") or "test_support" in name or name.startswith("test_")
            or name == "test_drivers.hpp")


class Layers:
    def __init__(self, root: pathlib.Path, layer_lines):
        self.root = root
        # folder (relative to root, e.g. "lib/families/p2os/driver") -> layer index (0 = highest)
        self.level = {}
        self.line_of = {}
        # folder -> (parent, name) for folders placed through lib/x/<name>...:
        # library code of one member never includes another member's.
        self.member_of = {}
        explicit = {f for _, folders in layer_lines for f in folders if "<" not in f}
        for index, (line_number, folders) in enumerate(layer_lines):
            for folder in folders:
                if "<" in folder:
                    parent, pattern = folder.split("/<", 1)
                    suffix = pattern.split(">", 1)[1]  # "" or "/driver" after lib/families/<name>
                    for sub in sorted((root / parent).iterdir()) if (root / parent).is_dir() else []:
                        relative = f"{parent}/{sub.name}{suffix}"
                        if sub.is_dir() and (root / relative).is_dir() and relative not in explicit:
                            self._place(relative, index, line_number)
                            self.member_of[relative] = (parent, sub.name)
                else:
                    self._place(folder, index, line_number)

    def _place(self, folder, index, line_number):
        if folder in self.level:
            raise LayerError(f"{folder} is on two lines ({self.line_of[folder]} and {line_number})")
        self.level[folder] = index
        self.line_of[folder] = line_number

    def folder_of(self, relative_dir: str):
        """The placed folder that owns a directory: itself or its nearest placed ancestor."""
        parts = relative_dir.split("/")
        for end in range(len(parts), 0, -1):
            candidate = "/".join(parts[:end])
            if candidate in self.level:
                return candidate
        return None


def check(root: pathlib.Path, architecture: pathlib.Path):
    findings = []
    layers = Layers(root, read_layer_lines(architecture))
    unplaced = set()
    for path in sorted((root / "lib").rglob("*")):
        if path.suffix not in SOURCE_SUFFIXES or not path.is_file():
            continue
        relative = path.relative_to(root)
        owner = layers.folder_of(str(relative.parent))
        if owner is None:
            unplaced.add(str(relative.parent))
            continue
        test_code = is_test_code(path)
        for number, text in enumerate(path.read_text(encoding="utf-8", errors="replace").splitlines(), 1):
            match = INCLUDE.match(text)
            if not match:
                continue
            included = match.group(1)
            if "/" not in included or (path.parent / included).is_file():
                continue  # beside the file: its own folder
            if included.startswith("support/"):
                if not test_code:
                    findings.append(f"{relative}:{number}: library code includes the tests' helper "
                                    f"\"{included}\" (tests/support)")
                continue
            target = layers.folder_of("lib/" + str(pathlib.PurePosixPath(included).parent))
            if target is None:
                findings.append(f"{relative}:{number}: \"{included}\" is in no folder of lib/ that "
                                f"{architecture.name} places")
                continue
            if target == owner:
                continue
            owner_member = layers.member_of.get(owner)
            target_member = layers.member_of.get(target)
            if (not test_code and owner_member and target_member and owner_member[0] == target_member[0]
                    and owner_member[1] != target_member[1] and layers.level[target] != layers.level[owner]):
                findings.append(f"{relative}:{number}: {owner} includes \"{included}\" from {target}: "
                                f"{owner_member[0]}/{owner_member[1]} and {target_member[0]}/{target_member[1]} "
                                f"are independent")
                continue
            if layers.level[target] > layers.level[owner]:
                continue
            if layers.level[target] == layers.level[owner] and test_code:
                continue
            relation = "a folder on its own line" if layers.level[target] == layers.level[owner] \
                else "a higher layer"
            findings.append(f"{relative}:{number}: {owner} (line {layers.line_of[owner]} of "
                            f"{architecture.name}) includes \"{included}\" from {target} (line "
                            f"{layers.line_of[target]}), {relation}")
    for folder in sorted(unplaced):
        findings.append(f"{folder}: a folder of lib/ with sources that {architecture.name} does not place")
    return findings


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--root", type=pathlib.Path,
                        default=pathlib.Path(__file__).resolve().parent.parent.parent)
    args = parser.parse_args()
    architecture = args.root / "docs" / "architecture.md"
    try:
        findings = check(args.root, architecture)
    except (LayerError, OSError) as error:
        print(f"check_layers: {error}", file=sys.stderr)
        return 2
    for finding in findings:
        print(finding)
    if findings:
        print(f"check_layers: {len(findings)} include(s) against the layers of "
              f"{architecture}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
