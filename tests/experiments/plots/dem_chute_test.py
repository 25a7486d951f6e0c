"""experiments/plots/dem_chute.py: the design form and its fit, the published coefficients and the in/out rule."""
import csv
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "..", "experiments", "plots"))
import dem_chute  # noqa: E402


class DesignForm(unittest.TestCase):
    def test_limits(self):
        self.assertAlmostEqual(dem_chute.design_coefficient(1.0, 1.0, 1.5), 2.0)
        self.assertAlmostEqual(dem_chute.design_coefficient(1e4, 1.0, 1.5), 1.5, places=7)

    def test_fit_recovers_k_and_alpha(self):
        fr = [0.5, 1.0, 2.0, 4.0, 8.0]
        c = [dem_chute.design_coefficient(f, 0.8, 1.7) for f in fr]
        k, alpha, rms = dem_chute.fit_design_form(fr, c)
        self.assertAlmostEqual(k, 0.8, places=9)
        self.assertAlmostEqual(alpha, 1.7, places=9)
        self.assertLess(rms, 1e-9)

    def test_too_few_or_inseparable_points(self):
        self.assertIsNone(dem_chute.fit_design_form([2.0], [1.0]))
        k, alpha, _ = dem_chute.fit_design_form([2.0, 2.0], [1.0, 3.0])
        self.assertIsNone(k)
        self.assertAlmostEqual(alpha, 2.0)


HEADER = "id,kind,fr_min,fr_max,c_min,c_max,flow,citation,url,note\n"


def write(folder, name, text):
    path = os.path.join(folder, name)
    with open(path, "w") as f:
        f.write(text)
    return path


class PublishedTable(unittest.TestCase):
    def test_the_committed_table_loads_and_every_row_names_its_source(self):
        rows = dem_chute.load_published(dem_chute.PUBLISHED)
        self.assertGreaterEqual(len(rows), 1)
        for r in rows:
            self.assertRegex(r["citation"], r"\b(19|20)\d\d\b", r["id"])  # authors' year
            self.assertTrue(r["url"].startswith("http"), r["id"])
            self.assertLessEqual(r["fr_min"], r["fr_max"])
            self.assertLessEqual(r["c_min"], r["c_max"])

    def test_a_row_without_a_citation_is_refused_naming_the_row(self):
        with tempfile.TemporaryDirectory() as d:
            path = write(d, "t.csv", "# comment\n" + HEADER + "a,range,1,2,0.5,1,flow, ,http://x,n\n")
            with self.assertRaisesRegex(ValueError, r"row 1 \(a\): no citation"):
                dem_chute.load_published(path)

    def test_a_reversed_range_or_a_bad_kind_is_refused(self):
        with tempfile.TemporaryDirectory() as d:
            path = write(d, "t.csv", HEADER + "a,range,3,2,0.5,1,flow,Someone 2020,http://x,n\n")
            with self.assertRaisesRegex(ValueError, "minimum above its maximum"):
                dem_chute.load_published(path)
            path = write(d, "u.csv", HEADER + "a,points,1,2,0.5,1,flow,Someone 2020,http://x,n\n")
            with self.assertRaisesRegex(ValueError, "neither range nor fit"):
                dem_chute.load_published(path)


class PublishedBand(unittest.TestCase):
    ROWS = [
        {"id": "a", "kind": "range", "fr_min": 0.5, "fr_max": 2.0, "c_min": 0.4, "c_max": 0.8},
        {"id": "b", "kind": "fit", "fr_min": 1.0, "fr_max": 4.0, "c_min": 5.0, "c_max": 5.0},
    ]

    def test_the_band_spans_the_rows_that_cover_the_froude_number(self):
        self.assertEqual(dem_chute.published_band(0.7, self.ROWS), (0.4, 0.8))
        self.assertEqual(dem_chute.published_band(1.5, self.ROWS), (0.4, 5.0))
        self.assertEqual(dem_chute.published_band(3.0, self.ROWS), (5.0, 5.0))
        self.assertIsNone(dem_chute.published_band(0.2, self.ROWS))

    def test_points_are_inside_only_within_the_band_at_their_own_froude_number(self):
        self.assertTrue(dem_chute.within_published(1.5, 3.0, self.ROWS))
        self.assertFalse(dem_chute.within_published(0.7, 3.0, self.ROWS))  # above a alone
        self.assertFalse(dem_chute.within_published(3.0, 4.9, self.ROWS))  # below b's single value
        self.assertFalse(dem_chute.within_published(9.0, 1.0, self.ROWS))  # no row covers Fr 9

    def test_the_plot_counts_the_points_by_the_rule(self):
        with tempfile.TemporaryDirectory() as d:
            table = write(d, "pub.csv", HEADER + "a,range,0.5,2,0.4,0.8,flow,Someone 2020,http://x,n\n"
                          "b,fit,1,4,5,5,flow,Someone 2021,http://y,n\n")
            write(d, "summary.csv", "name,solver,chute.mean.froude,chute.mean.coefficient,"
                  "chute.peak.froude,chute.peak.coefficient\n"
                  "r1,liggghts,1.5,3.0,0.7,3.0\n"
                  "r2,liggghts,0.7,0.6,3.0,5.0\n")
            dem_chute.main(d, table)
            self.assertTrue(os.path.exists(os.path.join(d, "dem_chute.png")))
            with open(os.path.join(d, "dem_chute_published.csv"), newline="") as f:
                rows = list(csv.DictReader(f))
            inside = {(r["name"], r["statistic"]): r["inside"] for r in rows if r["name"] != "count"}
            self.assertEqual(inside, {("r1", "mean"): "1", ("r1", "peak"): "0",
                                      ("r2", "mean"): "1", ("r2", "peak"): "1"})
            counts = {r["statistic"]: r["inside"] for r in rows if r["name"] == "count"}
            self.assertEqual(counts, {"mean": "2/2", "peak": "1/2"})


if __name__ == "__main__":
    unittest.main()
