"""The materials descriptors on numpy arrays, against scikit-image and numpy on the same arrays."""
import unittest

import numpy as np
from scipy import ndimage
from skimage.measure import euler_number, marching_cubes, mesh_surface_area

import solidtex


def blobs(shape, sigma, threshold, seed):
    """A random two-phase field: smoothed white noise above a threshold."""
    rng = np.random.default_rng(seed)
    return ndimage.gaussian_filter(rng.normal(size=shape), sigma, mode="wrap") > threshold


def ball(n, r):
    z, y, x = np.mgrid[0:n, 0:n, 0:n] - (n - 1) / 2 - 0.3
    return x * x + y * y + z * z <= r * r


class EulerNumberTest(unittest.TestCase):
    def test_equals_scikit_images_in_both_connectivities(self):
        for seed in range(4):
            volume = blobs((40, 36, 32), 2.0, 0.1 * seed, seed)
            for connectivity in (1, 3):
                self.assertEqual(solidtex.euler_number(volume, connectivity), euler_number(volume, connectivity))
            image = blobs((90, 80), 2.5, 0.1 * seed, seed)
            for connectivity in (1, 2):
                self.assertEqual(solidtex.euler_number(image, connectivity), euler_number(image, connectivity))

    def test_refuses_a_connectivity_the_field_has_not(self):
        with self.assertRaises(ValueError):
            solidtex.euler_number(np.ones((4, 4), bool), 3)


class SurfaceTest(unittest.TestCase):
    def test_crofton_and_marching_cubes_agree_on_a_ball(self):
        # Marching cubes on a binary field follows the voxels' staircase, cutting only its corners:
        # it overestimates a smooth surface by about 8 % (Lindblad 2005), where Crofton's count of
        # crossings along 13 directions estimates the sphere's own area.
        r, n = 20, 56
        b = ball(n, r)
        crofton = solidtex.minkowski(b, periodic=True)["surface_density"] * b.size
        vertices, faces, _, _ = marching_cubes(b.astype(np.float32), 0.5)
        mc = mesh_surface_area(vertices, faces)
        self.assertAlmostEqual(crofton / (4 * np.pi * r * r), 1.0, delta=0.03)
        self.assertGreater(mc / crofton, 1.04)
        self.assertLess(mc / crofton, 1.12)


class TwoPointCorrelationTest(unittest.TestCase):
    def test_periodic_estimate_is_numpys_autocorrelation(self):
        volume = blobs((32, 40, 48), 2.0, 0.2, 7)
        f = np.fft.rfftn(volume.astype(float))
        auto = np.fft.irfftn(f * np.conj(f), s=volume.shape) / volume.size
        s2 = solidtex.two_point_correlation(volume, periodic=True, max_distance=12)
        np.testing.assert_allclose(s2["x"], auto[0, 0, :13], atol=1e-9)
        np.testing.assert_allclose(s2["y"], auto[0, :13, 0], atol=1e-9)
        np.testing.assert_allclose(s2["z"], auto[:13, 0, 0], atol=1e-9)
        self.assertAlmostEqual(s2["phase_fraction"], volume.mean(), places=12)

    def test_zero_padded_estimate_counts_pairs_inside_the_field(self):
        image = blobs((50, 60), 2.0, 0.0, 3)
        s2 = solidtex.two_point_correlation(image, max_distance=10)
        for r in range(11):
            self.assertAlmostEqual(s2["x"][r], (image[:, : 60 - r] & image[:, r:]).mean(), places=9)
            self.assertAlmostEqual(s2["y"][r], (image[: 50 - r, :] & image[r:, :]).mean(), places=9)


class ChordsTest(unittest.TestCase):
    def test_counts_the_runs_inside_each_line(self):
        image = blobs((30, 70), 1.5, 0.0, 5)
        expected = np.zeros(71, np.int64)
        for row in image:
            labels, count = ndimage.label(row)
            for run in range(1, count + 1):
                where = np.flatnonzero(labels == run)
                if where[0] > 0 and where[-1] < len(row) - 1:
                    expected[len(where)] += 1
        np.testing.assert_array_equal(solidtex.chord_lengths(image)["x"], expected)

    def test_lineal_path_starts_at_the_fraction(self):
        volume = blobs((20, 20, 20), 1.5, 0.0, 2)
        lineal = solidtex.lineal_path(volume, 5)
        for axis in "xyz":
            self.assertAlmostEqual(lineal[axis][0], volume.mean(), places=12)
            self.assertTrue(np.all(np.diff(lineal[axis]) <= 0))


class LocalThicknessTest(unittest.TestCase):
    def test_is_the_largest_inscribed_ball_by_brute_force(self):
        image = blobs((40, 44), 2.0, -0.2, 9)
        result = solidtex.local_thickness(image, sizes=12)
        depth = ndimage.distance_transform_edt(image)
        expected = np.zeros(image.shape, np.float32)
        yy, xx = np.mgrid[0:40, 0:44]
        for r in result["radii"]:  # largest first: a pixel keeps the first radius that covers it
            for cy, cx in zip(*np.nonzero(depth >= r)):
                covered = ((yy - cy) ** 2 + (xx - cx) ** 2 < r * r) & (expected == 0) & image
                expected[covered] = r
        np.testing.assert_allclose(result["thickness"], expected, rtol=1e-6)


class TortuosityTest(unittest.TestCase):
    def test_straight_channels_have_one_and_a_dead_end_field_refuses(self):
        channels = np.zeros((12, 10, 30), bool)
        channels[::3, ::2, :] = True
        self.assertAlmostEqual(solidtex.tortuosity(channels, axis=2)["factor"], 1.0, places=5)
        with self.assertRaises(solidtex.Error):
            solidtex.tortuosity(channels, axis=0)


if __name__ == "__main__":
    unittest.main()
