"""The Python module on the library: numpy in and out, the command line's bytes, no file unless asked."""
import json
import os
import shutil
import signal
import subprocess
import sys
import tempfile
import time
import unittest

import numpy as np
from PIL import Image

import solidtex

CLI = os.environ["SOLIDTEX_CLI"]
COINS = os.path.join(os.environ["SOLIDTEX_DATA_DIR"], "particles", "coins.png")
SMARTIES = os.path.join(os.environ["SOLIDTEX_DATA_DIR"], "particles", "smarties.png")
CT = os.path.join(os.environ["SOLIDTEX_DATA_DIR"], "volumes", "ct_stent_64.vdb")


def cli(*arguments, **kwargs):
    return subprocess.run([CLI, *arguments], capture_output=True, text=True, **kwargs)


def same_analysis(test, a, b):
    """Two analyze() results agree: their reports and their label images."""
    a, b = dict(a), dict(b)
    np.testing.assert_array_equal(a.pop("particle_labels"), b.pop("particle_labels"))
    test.assertEqual(a, b)


def discs_photo():
    """An RGB uint8 photo made in memory: 30 dark discs of radius 5 to 8 on a light, grainy ground."""
    rng = np.random.default_rng(4)
    y, x = np.mgrid[0:150, 0:150]
    photo = np.empty((150, 150, 3), np.uint8)
    photo[:] = (214, 206, 196)
    photo = np.clip(photo + rng.normal(0, 3, photo.shape), 0, 255).astype(np.uint8)
    for row in range(6):
        for col in range(5):
            cy, cx, r = 12 + 25 * row + rng.integers(-2, 3), 15 + 30 * col + rng.integers(-3, 4), rng.integers(5, 9)
            photo[(y - cy) ** 2 + (x - cx) ** 2 <= r * r] = (70, 52, 40)
    return photo


class InMemoryTest(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.photo = discs_photo()
        cls.folder = tempfile.TemporaryDirectory()
        empty = os.path.join(cls.folder.name, "empty")
        os.mkdir(empty)
        before = os.getcwd()
        os.chdir(empty)
        try:
            cls.solid = solidtex.particles(cls.photo, size=24, seed=5)
        finally:
            os.chdir(before)
        cls.left_behind = os.listdir(empty)

    @classmethod
    def tearDownClass(cls):
        cls.folder.cleanup()

    def test_no_file_is_written_when_none_is_asked_for(self):
        self.assertEqual(self.left_behind, [])

    def test_the_arrays_are_the_command_lines_bytes_for_the_same_image_saved_as_png(self):
        png = os.path.join(self.folder.name, "discs.png")
        Image.fromarray(self.photo).save(png)
        npy = os.path.join(self.folder.name, "npy")
        vdb = os.path.join(self.folder.name, "cli.vdb")
        run = cli("particles", png, "-o", vdb, "--size", "24", "--seed", "5", "--npy", npy, "--quiet")
        self.assertEqual(run.returncode, 0, run.stderr)
        ids, color = np.load(os.path.join(npy, "particle_id.npy")), np.load(os.path.join(npy, "color.npy"))
        self.assertEqual(ids.tobytes(), self.solid["particle_id"].tobytes())
        self.assertEqual(color.tobytes(), self.solid["color"].tobytes())
        self.assertEqual(ids.shape, self.solid["particle_id"].shape)
        self.assertEqual(color.shape, self.solid["color"].shape)

    def test_the_report_describes_the_arrays(self):
        ids, report = self.solid["particle_id"], self.solid["report"]
        self.assertEqual(ids.shape, (24, 24, 24))
        self.assertEqual(self.solid["color"].shape, (24, 24, 24, 3))
        self.assertAlmostEqual(report["volume"]["volume_fraction"], float((ids > 0).mean()), places=12)
        self.assertEqual(report["volume"]["particles"], len(np.unique(ids[ids > 0])))
        self.assertEqual(report["photo"]["particle_count"], 30)
        self.assertEqual(report["body_form"], {"form": 0, "fitted": False})  # the paper's boxes unless asked

    def test_phases_give_the_command_lines_phase_array(self):
        solid = solidtex.particles(SMARTIES, size=32, seed=3, phases=5)
        npy = os.path.join(self.folder.name, "phases_npy")
        run = cli("particles", SMARTIES, "-o", os.path.join(self.folder.name, "phases.vdb"), "--size", "32",
                  "--seed", "3", "--phases", "5", "--npy", npy, "--quiet")
        self.assertEqual(run.returncode, 0, run.stderr)
        phase = np.load(os.path.join(npy, "phase.npy"))
        self.assertEqual(phase.dtype, np.uint8)
        self.assertEqual(phase.tobytes(), solid["phase"].tobytes())
        np.testing.assert_array_equal(phase > 0, solid["particle_id"] > 0)
        self.assertEqual(solid["report"]["phases"]["count"], 5)
        for phase_class in solid["report"]["phases"]["classes"]:
            self.assertEqual(len(phase_class["lab"]), 3)
            self.assertGreaterEqual(phase_class["grain"], 0)
        self.assertLessEqual(int(phase.max()), 5)
        # One phase per particle.
        ids = solid["particle_id"]
        for particle in np.unique(ids[ids > 0]):
            self.assertEqual(len(np.unique(phase[ids == particle])), 1)
        self.assertNotIn("phase", self.solid)

    def test_grey_and_float_images_read_as_their_rgb_uint8_form(self):
        grey = self.photo[:, :, 0]
        as_rgb = solidtex.analyze(np.repeat(grey[:, :, None], 3, axis=2))
        same_analysis(self, solidtex.analyze(grey), as_rgb)
        as_float = solidtex.analyze(self.photo.astype(np.float64) / 255)
        self.assertEqual(as_float["particle_count"], solidtex.analyze(self.photo)["particle_count"])

    def test_the_label_image_holds_each_particle_with_its_reported_area(self):
        analysis = solidtex.analyze(self.photo)
        labels = analysis["particle_labels"]
        self.assertEqual((labels.shape, labels.dtype), ((150, 150), np.int32))
        areas = np.bincount(labels.ravel(), minlength=analysis["particle_count"] + 1)
        self.assertEqual(len(areas), analysis["particle_count"] + 1)
        for particle in analysis["particles"]:
            self.assertEqual(areas[particle["id"]], particle["area"])
        dark = self.photo[:, :, 0] < 128
        self.assertGreater(np.mean((labels > 0) == dark), 0.99)

    def test_outlines_are_the_command_lines(self):
        sharp = solidtex.analyze(self.photo)
        self.assertEqual(sharp["outlines"], "watershed")
        self.assertLess(sharp["outline_blur"], 1.0)
        self.assertEqual(solidtex.analyze(self.photo, outlines="half-maximum")["outlines"], "half-maximum")

    def test_a_mask_array_reads_as_the_same_mask_saved_as_png(self):
        dark = self.photo[:, :, 0] < 128
        png = os.path.join(self.folder.name, "mask.png")
        Image.fromarray(np.where(dark, 255, 0).astype(np.uint8)).save(png)
        from_file = solidtex.analyze(self.photo, mask=png)
        same_analysis(self, solidtex.analyze(self.photo, mask=dark), from_file)
        same_analysis(self, solidtex.analyze(self.photo, mask=np.where(dark, 1.0, 0.0)), from_file)
        self.assertGreaterEqual(from_file["particle_count"], 25)
        with self.assertRaises(solidtex.Error) as error:
            solidtex.analyze(self.photo, mask=dark[:100])
        self.assertIn("mask is 150x100 but the photo is 150x150", str(error.exception))
        with self.assertRaises(TypeError) as error:
            solidtex.analyze(self.photo, mask=3)
        self.assertIn("mask", str(error.exception))

    def test_output_and_report_write_the_volume_and_the_report(self):
        vdb = os.path.join(self.folder.name, "python.vdb")
        report = os.path.join(self.folder.name, "python.json")
        solid = solidtex.particles(self.photo, size=24, seed=5, output=vdb, report=report)
        np.testing.assert_array_equal(solid["particle_id"], self.solid["particle_id"])
        with open(report) as f:
            self.assertEqual(json.load(f)["volume"], solid["report"]["volume"])
        from_file = solidtex.compare(self.photo, vdb, axis_planes=4, oblique_planes=0)
        from_arrays = solidtex.compare(self.photo, solid, axis_planes=4, oblique_planes=0)
        self.assertEqual(from_file["mode"], "particles")
        self.assertEqual(from_arrays | {"volume": vdb}, from_file)


class SynthesizeTest(unittest.TestCase):
    def test_a_numpy_volume_exemplar_gives_a_volume_of_its_values_with_its_layers(self):
        rng = np.random.default_rng(1)
        z = np.arange(32)[:, None, None]
        layers = np.broadcast_to(0.5 + 0.4 * np.sin(z / 3.0), (32, 32, 32))
        exemplar = (layers + 0.05 * rng.normal(size=(32, 32, 32))).astype(np.float32)
        made = solidtex.synthesize(exemplar, size=32, measure=False)
        density = made["density"]
        self.assertEqual(density.shape, (32, 32, 32))
        self.assertTrue(np.isin(density, exemplar).all())  # every voxel is a copy of an exemplar voxel
        # The layers stay across z: slices' means vary along z, hardly along x or y.
        along = [density.mean(axis=axes).std() for axes in [(1, 2), (0, 2), (0, 1)]]
        self.assertGreater(along[0], 4 * max(along[1], along[2]))
        self.assertEqual(made["report"]["exemplar"]["name"], "array")

    def test_a_vdb_exemplar_gives_the_command_lines_bytes(self):
        with tempfile.TemporaryDirectory() as folder:
            npy = os.path.join(folder, "npy")
            run = cli("synthesize", CT, "-o", os.path.join(folder, "s.vdb"), "--size", "16", "--no-quality",
                      "--npy", npy, "--quiet")
            self.assertEqual(run.returncode, 0, run.stderr)
            made = solidtex.synthesize(CT, size=16, measure=False)
            self.assertEqual(np.load(os.path.join(npy, "density.npy")).tobytes(), made["density"].tobytes())

    def test_a_numpy_photo_gives_the_command_lines_bytes_and_compares_with_itself(self):
        photo = np.asarray(Image.open(COINS).convert("RGB"))[:64, :64].copy()
        with tempfile.TemporaryDirectory() as folder:
            png, npy = os.path.join(folder, "crop.png"), os.path.join(folder, "npy")
            Image.fromarray(photo).save(png)
            run = cli("synthesize", png, "-o", os.path.join(folder, "s.vdb"), "--size", "32", "--no-quality",
                      "--npy", npy, "--quiet")
            self.assertEqual(run.returncode, 0, run.stderr)
            made = solidtex.synthesize(photo, size=32, measure=False)
            self.assertEqual(np.load(os.path.join(npy, "color.npy")).tobytes(), made["color"].tobytes())
            mask = os.path.join(folder, "halves.png")
            Image.fromarray(np.repeat(np.uint8([0, 255]), 32)[None, :].repeat(64, axis=0)).save(mask)
            halves = solidtex.compare(photo, made, mode="continuous", measures="s2", phase_mask=mask)
        self.assertEqual(len(halves["materials"]["phases"]), 2)
        comparison = solidtex.compare(photo, made, mode="continuous")
        self.assertEqual(comparison["mode"], "continuous")
        self.assertEqual(comparison["dims"], [32, 32, 32])

    def test_plane_exemplars_give_the_command_lines_bytes_and_each_planes_quality(self):
        planes = os.path.join(os.environ["SOLIDTEX_DATA_DIR"], "continuous", "planes")
        xy, xz, yz = (os.path.join(planes, f"bedded_{p}.png") for p in ("xy", "xz", "yz"))
        with tempfile.TemporaryDirectory() as folder:
            npy = os.path.join(folder, "npy")
            run = cli("synthesize", xy, "--photo-xz", xz, "--photo-yz", yz, "-o", os.path.join(folder, "s.vdb"),
                      "--size", "32", "--no-quality", "--npy", npy, "--quiet")
            self.assertEqual(run.returncode, 0, run.stderr)
            made = solidtex.synthesize(xy, photo_xz=xz, photo_yz=yz, size=32)
            self.assertEqual(np.load(os.path.join(npy, "color.npy")).tobytes(), made["color"].tobytes())
        report = made["report"]
        self.assertNotIn("quality", report)
        self.assertEqual([report["planes"][p]["exemplar"] for p in ("yz", "xz", "xy")],
                         ["bedded_yz.png", "bedded_xz.png", "bedded_xy.png"])
        self.assertGreater(report["planes"]["xz"]["quality"]["axis"]["completeness"], 0)
        with self.assertRaisesRegex(solidtex.Error, "differ in size"):
            solidtex.synthesize(xy, photo_xz=COINS, size=32)

    def test_a_grown_photo_solid_gives_the_command_lines_bytes(self):
        photo = np.asarray(Image.open(COINS).convert("RGB"))[:48, :48].copy()
        growth = ["--grow-from", "32", "--dims", "40", "20", "18"]
        with tempfile.TemporaryDirectory() as folder:
            png, npy = os.path.join(folder, "crop.png"), os.path.join(folder, "npy")
            Image.fromarray(photo).save(png)
            run = cli("synthesize", png, "-o", os.path.join(folder, "s.vdb"), *growth, "--no-quality",
                      "--npy", npy, "--quiet")
            self.assertEqual(run.returncode, 0, run.stderr)
            made = solidtex.synthesize(photo, grow_from=32, dims=(40, 20, 18), bricks=24, measure=False)
            self.assertEqual(made["color"].shape, (18, 20, 40, 3))
            self.assertEqual(np.load(os.path.join(npy, "color.npy")).tobytes(), made["color"].tobytes())
        self.assertEqual(made["report"]["growth"]["bricks"], 2)


class KeywordsTest(unittest.TestCase):
    def test_a_keyword_of_the_wrong_type_is_a_type_error_naming_it(self):
        for keywords, name in [({"size": "32"}, "size"), ({"size": True}, "size"), ({"seed": 1.5}, "seed"),
                               ({"dims": (8, 8)}, "dims"), ({"split": 1}, "split"), ({"output": 3}, "output"),
                               ({"phases": True}, "phases"), ({"phases": 2.0}, "phases"),
                               ({"body_form": True}, "body_form")]:
            with self.assertRaises(TypeError) as error:
                solidtex.particles(COINS, **keywords)
            self.assertIn(name, str(error.exception))
        with self.assertRaises(TypeError) as error:
            solidtex.particles(COINS, sise=32)
        self.assertIn("sise", str(error.exception))

    def test_a_value_out_of_range_is_a_value_error_naming_the_keyword_not_a_flag(self):
        for keywords, name in [({"views": 7}, "views"), ({"scale": 100.0}, "scale"),
                               ({"particle_texture": "x"}, "particle_texture"), ({"placer": "x"}, "placer"),
                               ({"seed": -1}, "seed"), ({"outlines": "sharp"}, "outlines"),
                               ({"phases": 0}, "phases"), ({"phases": "two"}, "phases"),
                               ({"body_form": 1.5}, "body_form"), ({"body_form": "disc"}, "body_form")]:
            with self.assertRaises(ValueError) as error:
                solidtex.particles(COINS, size=16, **keywords)
            self.assertIn(name, str(error.exception))
            self.assertNotIn("--", str(error.exception))

    def test_a_photo_that_cannot_be_read_is_solidtex_error(self):
        with self.assertRaises(solidtex.Error) as error:
            solidtex.particles("missing.png", size=16)
        self.assertIn("missing.png: file not found", str(error.exception))
        with self.assertRaises(TypeError):
            solidtex.analyze(3)

    def test_a_path_is_never_parsed_as_an_option(self):
        with tempfile.TemporaryDirectory() as folder:
            shutil.copy(COINS, os.path.join(folder, "-in.png"))
            shutil.copy(COINS, os.path.join(folder, "--help"))
            before = os.getcwd()
            os.chdir(folder)
            try:
                for name in ["-in.png", "--help"]:
                    self.assertEqual(solidtex.analyze(name)["particle_count"], 24)
            finally:
                os.chdir(before)


SCRIPT = """
import sys, solidtex
print("started", flush=True)
try:
    solidtex.particles(sys.argv[1], size=80, seed=2, output=sys.argv[2], report=sys.argv[3])
except KeyboardInterrupt:
    print("interrupted", flush=True)
    sys.exit(0)
print("finished", flush=True)
"""


class ProcessTest(unittest.TestCase):
    def test_ctrl_c_stops_the_call_and_leaves_none_of_its_outputs(self):
        with tempfile.TemporaryDirectory() as folder:
            vdb, report = os.path.join(folder, "a.vdb"), os.path.join(folder, "a.json")
            child = subprocess.Popen([sys.executable, "-c", SCRIPT, COINS, vdb, report], stdout=subprocess.PIPE,
                                     text=True)
            self.assertEqual(child.stdout.readline().strip(), "started")
            time.sleep(3)
            sent = time.monotonic()
            child.send_signal(signal.SIGINT)
            out, _ = child.communicate(timeout=120)
            print(f"\nCtrl-C to exit: {time.monotonic() - sent:.2f} s", file=sys.stderr)
            self.assertEqual(out.strip(), "interrupted")
            self.assertEqual(os.listdir(folder), [])

    def test_a_missing_temporary_folder_does_not_matter_when_nothing_is_written(self):
        environment = dict(os.environ, TMPDIR="/nonexistent/solidtex")
        code = "import solidtex, sys; print(solidtex.particles(sys.argv[1], size=16)['report']['volume']['particles'] > 0)"
        run = subprocess.run([sys.executable, "-c", code, COINS], capture_output=True, text=True, env=environment)
        self.assertEqual(run.stdout.strip(), "True", run.stderr)


if __name__ == "__main__":
    unittest.main()
