"""The Python module against the command line: same bytes, same messages, arrays equal to the files."""
import os
import subprocess
import tempfile
import unittest

import numpy as np

import solidtex

CLI = os.environ["SOLIDTEX_CLI"]
COINS = os.path.join(os.environ["SOLIDTEX_DATA_DIR"], "particles", "coins.png")


def cli(*arguments):
    return subprocess.run([CLI, *arguments], capture_output=True, text=True)


class ParticlesTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.folder = tempfile.TemporaryDirectory()
        cls.vdb = os.path.join(cls.folder.name, "python.vdb")
        cls.npy = os.path.join(cls.folder.name, "npy")
        cls.solid = solidtex.particles(COINS, output=cls.vdb, size=24, seed=5, npy=cls.npy)

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def test_the_vdb_is_the_command_lines_byte_for_byte(self):
        made = os.path.join(self.folder.name, "cli.vdb")
        self.assertEqual(cli("particles", COINS, "-o", made, "--size", "24", "--seed", "5", "--quiet").returncode, 0)
        with open(self.vdb, "rb") as python, open(made, "rb") as command_line:
            self.assertEqual(python.read(), command_line.read())

    def test_arrays_are_the_volume_and_the_report_describes_them(self):
        ids, color = self.solid["particle_id"], self.solid["color"]
        self.assertEqual(ids.shape, (24, 24, 24))
        self.assertEqual(color.shape, (24, 24, 24, 3))
        report = self.solid["report"]
        self.assertAlmostEqual(report["volume"]["volume_fraction"], float((ids > 0).mean()), places=12)
        self.assertEqual(report["volume"]["particles"], len(np.unique(ids[ids > 0])))

    def test_numpy_reads_the_npy_export_as_the_volume(self):
        np.testing.assert_array_equal(np.load(os.path.join(self.npy, "particle_id.npy")), self.solid["particle_id"])
        np.testing.assert_array_equal(np.load(os.path.join(self.npy, "color.npy")), self.solid["color"])


class ErrorsTest(unittest.TestCase):
    def assert_same_message(self, error, arguments):
        run = cli(*arguments)
        self.assertEqual(run.stderr.strip(), "solidtex: error: " + str(error.exception))
        return run.returncode

    def test_a_wrong_option_is_a_value_error_with_the_command_lines_message(self):
        with self.assertRaises(ValueError) as error:
            solidtex.particles(COINS, size=4096)
        self.assertEqual(self.assert_same_message(error, ["particles", COINS, "-o", "x.vdb", "--size", "4096"]), 2)
        with self.assertRaises(ValueError):
            solidtex.particles(COINS, sise=32)

    def test_a_failed_command_raises_solidtex_error_with_its_message(self):
        with self.assertRaises(solidtex.Error) as error:
            solidtex.particles("missing.png", size=16)
        self.assertEqual(self.assert_same_message(error, ["particles", "missing.png", "-o", "x.vdb", "--size", "16"]), 1)


class ReportsTest(unittest.TestCase):
    def test_analyze_and_compare_return_their_reports(self):
        with tempfile.TemporaryDirectory() as folder:
            report = os.path.join(folder, "r.json")
            self.assertEqual(cli("analyze", COINS, "--report", report).returncode, 0)
            with open(report) as f:
                import json

                self.assertEqual(solidtex.analyze(COINS), json.load(f))
            solid = os.path.join(folder, "s.vdb")
            solidtex.particles(COINS, output=solid, size=32)
            comparison = solidtex.compare(COINS, solid, axis_planes=4, oblique_planes=0)
            self.assertIn("sections", json.dumps(comparison))


if __name__ == "__main__":
    unittest.main()
