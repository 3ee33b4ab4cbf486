#!/usr/bin/env python3
"""Tests of check_layers.py on small trees made for each case: what it
accepts, what it reports (file:line and both layers), and what it refuses."""

import pathlib
import sys
import tempfile
import unittest

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))
import check_layers  # noqa: E402

DIAGRAM = """# Architecture

<!-- layers -->
```
tools/  player-serve
lib/high   lib/side      the top of the library
lib/fam/<name>           families
lib/fam                  what they share
lib/low                  the bottom
```
"""


class LayerTree:
    def __init__(self, directory, diagram=DIAGRAM):
        self.root = pathlib.Path(directory)
        (self.root / "docs").mkdir()
        (self.root / "docs" / "architecture.md").write_text(diagram)

    def write(self, path, *includes):
        file = self.root / path
        file.parent.mkdir(parents=True, exist_ok=True)
        file.write_text("#pragma once\n" + "".join(f'#include "{i}"\n' for i in includes))

    def findings(self):
        return check_layers.check(self.root, self.root / "docs" / "architecture.md")


class CheckLayersTest(unittest.TestCase):
    def setUp(self):
        self.directory = tempfile.TemporaryDirectory()
        self.tree = LayerTree(self.directory.name)
        self.tree.write("lib/low/low.hpp")
        self.tree.write("lib/fam/shared.hpp", "low/low.hpp")
        self.tree.write("lib/fam/a/a.hpp", "fam/shared.hpp", "low/low.hpp")
        self.tree.write("lib/fam/b/b.hpp", "fam/shared.hpp")
        self.tree.write("lib/side/side.hpp")
        self.tree.write("lib/high/high.hpp", "fam/a/a.hpp", "low/low.hpp", "high/other.hpp")
        self.tree.write("lib/high/other.hpp", "beside.hpp")
        self.tree.write("lib/high/beside.hpp")

    def tearDown(self):
        self.directory.cleanup()

    def test_a_tree_that_keeps_its_layers_passes(self):
        self.assertEqual(self.tree.findings(), [])

    def test_a_lower_layer_including_a_higher_one_is_named_with_both(self):
        self.tree.write("lib/low/low.hpp", "fam/a/a.hpp")
        self.assertEqual(self.tree.findings(), [
            'lib/low/low.hpp:2: lib/low (line 9 of architecture.md) includes "fam/a/a.hpp" '
            'from lib/fam/a (line 7), a higher layer'])

    def test_folders_on_one_line_are_independent_except_in_tests(self):
        self.tree.write("lib/high/high.hpp", "side/side.hpp")
        self.tree.write("lib/fam/a/a_test.cpp", "fam/b/b.hpp")
        self.tree.write("lib/fam/b/b.cpp", "fam/a/a.hpp")
        self.assertEqual(self.tree.findings(), [
            'lib/fam/b/b.cpp:2: lib/fam/b (line 7 of architecture.md) includes "fam/a/a.hpp" '
            'from lib/fam/a (line 7), a folder on its own line',
            'lib/high/high.hpp:2: lib/high (line 6 of architecture.md) includes "side/side.hpp" '
            'from lib/side (line 6), a folder on its own line'])

    def test_test_helpers_only_in_test_code(self):
        self.tree.write("lib/low/low_test.cpp", "support/eventually.hpp")
        self.tree.write("lib/low/low.cpp", "support/eventually.hpp")
        findings = self.tree.findings()
        self.assertEqual(len(findings), 1)
        self.assertTrue(findings[0].startswith('lib/low/low.cpp:2: library code includes'))

    def test_the_tools_are_above_the_library(self):
        self.tree.write("lib/high/high.hpp", "../tools/common/exit_status.hpp")
        self.tree.write("lib/side/side.hpp", "tools/common/exit_status.hpp")
        self.assertIn("is in no folder of lib/", self.tree.findings()[0])

    def test_folders_the_diagram_does_not_place_are_reported(self):
        self.tree.write("lib/newcomer/new.hpp")
        self.tree.write("lib/high/high.hpp", "newcomer/new.hpp")
        self.assertEqual(self.tree.findings(), [
            'lib/high/high.hpp:2: "newcomer/new.hpp" is in no folder of lib/ that architecture.md places',
            "lib/newcomer: a folder of lib/ with sources that architecture.md does not place"])

    def test_a_diagram_without_its_marker_is_refused(self):
        (self.tree.root / "docs" / "architecture.md").write_text(DIAGRAM.replace("<!-- layers -->", ""))
        with self.assertRaises(check_layers.LayerError):
            self.tree.findings()

    def test_a_folder_on_two_lines_is_refused(self):
        (self.tree.root / "docs" / "architecture.md").write_text(
            DIAGRAM.replace("lib/low                  the bottom", "lib/low\nlib/high"))
        with self.assertRaises(check_layers.LayerError):
            self.tree.findings()


class MemberParts(unittest.TestCase):
    DIAGRAM = """# Architecture

<!-- layers -->
```
lib/fam/<name>            a member's top
lib/fam/<name>/driver     a member's driver
lib/fam/<name>/protocol   a member's bytes
```
"""

    def test_parts_of_a_member_follow_their_lines(self):
        with tempfile.TemporaryDirectory() as directory:
            tree = LayerTree(directory, self.DIAGRAM)
            tree.write("lib/fam/a/protocol/bytes.hpp")
            tree.write("lib/fam/a/driver/driver.hpp", "fam/a/protocol/bytes.hpp")
            tree.write("lib/fam/a/spec.hpp", "fam/a/driver/driver.hpp")
            self.assertEqual(tree.findings(), [])
            tree.write("lib/fam/a/protocol/up.hpp", "fam/a/driver/driver.hpp")
            findings = tree.findings()
            self.assertEqual(len(findings), 1, findings)
            self.assertIn("lib/fam/a/protocol/up.hpp:2", findings[0])

    def test_one_member_never_includes_another(self):
        with tempfile.TemporaryDirectory() as directory:
            tree = LayerTree(directory, self.DIAGRAM)
            tree.write("lib/fam/b/protocol/bytes.hpp")
            tree.write("lib/fam/a/driver/driver.hpp", "fam/b/protocol/bytes.hpp")
            findings = tree.findings()
            self.assertEqual(len(findings), 1, findings)
            self.assertIn("lib/fam/a and lib/fam/b are independent", findings[0])
            # Test code may use another member (a robot carrying another family's sensor).
            tree.write("lib/fam/a/driver/driver.hpp")
            tree.write("lib/fam/a/driver/rig_test.cpp", "fam/b/protocol/bytes.hpp")
            self.assertEqual(tree.findings(), [])


if __name__ == "__main__":
    unittest.main()
