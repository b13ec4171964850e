"""The benchmark table's arithmetic, without measuring anything: each benchmark's fastest
repetition (never an aggregate), what a row is judged by, a regression, and the agreement of
two runs' ratios. Usage: table_test.py"""
import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import table  # noqa: E402


def bench(name, ms, run_type="iteration", **counters):
    return dict(name=name, real_time=ms, time_unit="ms", run_type=run_type, **counters)


def row(key, value, unit="ms", ratio=None, yardsticks=None, better="lower"):
    return dict(key=key, value=value, unit=unit, ratio=ratio, yardsticks=yardsticks,
                better=better)


class BestRepetitions(unittest.TestCase):
    def test_keeps_each_benchmarks_fastest_repetition_and_no_aggregate(self):
        runs = [bench("BM_Plane", 25.0), bench("BM_Plane", 18.5), bench("BM_Plane", 21.0),
                bench("BM_Plane_mean", 10.0, "aggregate"), bench("BM_Cube", 230.0),
                bench("BM_Search", 400.0, seeds_per_s=5e5), bench("BM_Search", 280.0, seeds_per_s=7e5)]
        best = {b["name"]: b for b in table.best_repetitions(runs)}
        self.assertEqual(set(best), {"BM_Plane", "BM_Cube", "BM_Search"})
        self.assertEqual(best["BM_Plane"]["real_time"], 18.5)
        self.assertEqual(best["BM_Search"]["seeds_per_s"], 7e5)

    def test_compares_times_in_their_units(self):
        runs = [bench("BM_Field", 6.0), dict(bench("BM_Field", 5000.0), time_unit="us")]
        self.assertEqual(table.best_repetitions(runs)[0]["time_unit"], "us")


class Judging(unittest.TestCase):
    def test_a_row_is_judged_by_its_peer_ratio_then_its_yardsticks_then_its_value(self):
        self.assertEqual(table.judged(row("a", 20, ratio=500), row("a", 18, ratio=520)),
                         (500, 520, True))
        self.assertEqual(table.judged(row("b", 900, yardsticks=7), row("b", 800, yardsticks=6)),
                         (7, 6, False))
        self.assertEqual(table.judged(row("c", 1.2, unit="×"), row("c", 1.1, unit="×")),
                         (1.2, 1.1, False))

    def test_a_regression_is_more_than_a_fifth_worse(self):
        before = {"rows": [row("p", 900, yardsticks=6.0), row("q", 20, ratio=500)]}
        self.assertEqual(table.compare([row("p", 950, yardsticks=7.1), row("q", 20, ratio=420)],
                                       before), [])
        worse = table.compare([row("p", 950, yardsticks=7.3), row("q", 20, ratio=410)], before)
        self.assertEqual([w.split(":")[0] for w in worse], ["p", "q"])


class Agreement(unittest.TestCase):
    def test_counts_the_rows_within_a_quarter_of_the_committed_ratio(self):
        committed = {"rows": [row("plane", 18, ratio=500), row("pavilion", 900, yardsticks=7.0),
                              row("markov", 1.2, unit="×"), row("first_run", 234, unit="s")]}
        here = [row("plane", 30, ratio=300), row("pavilion", 800, yardsticks=6.0),
                row("markov", 1.25, unit="×"), row("first_run", 250, unit="s"),
                row("new_row", 1, yardsticks=1)]
        lines, agree, rated = table.agreement(here, committed)
        self.assertEqual((agree, rated), (2, 3))  # plane 40 % apart; no ratio for first_run
        self.assertIn("apart", lines[0])
        self.assertTrue(lines[1].startswith("pavilion") and "-14.3%" in lines[1])


if __name__ == "__main__":
    unittest.main()
