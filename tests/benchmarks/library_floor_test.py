"""library_floor.py's arithmetic, without measuring anything: a perf report read as shares of
its samples, and the shares grouped into curdle's own code, the process's and the writers'
libraries. Usage: library_floor_test.py"""
import sys
import unittest
from pathlib import Path

sys.path.insert(0, str(Path(__file__).resolve().parent))
import library_floor  # noqa: E402

REPORT = """# Samples: 6K of event 'cpu-clock:pppH'
#
# Overhead       Samples  Shared Object
# ........  ............  ........................
#
    22.28%          1400  libsqlite3.so.0.8.6
    21.85%          1300  curdle
    17.43%          1100  libc.so.6
     9.37%           600  libcairo.so.2.11600.0
     8.80%           500  [kernel.kallsyms]
     4.56%           300  libgdal.so.32.3.6.2
     2.71%           200  ld-linux-x86-64.so.2
     1.99%           100  libstdc++.so.6.0.30
     0.64%           100  libcurdle_gpkg.so
"""


class Report(unittest.TestCase):
    def test_reads_each_objects_samples_as_a_share_and_skips_the_header(self):
        shares = library_floor.shares_in_report(REPORT)
        self.assertEqual(len(shares), 9)
        self.assertAlmostEqual(shares["libsqlite3.so.0.8.6"], 1400 / 5600)
        self.assertAlmostEqual(shares["[kernel.kallsyms]"], 500 / 5600)
        self.assertAlmostEqual(sum(shares.values()), 1)

    def test_an_empty_report_has_no_shares(self):
        self.assertEqual(library_floor.shares_in_report("# nothing sampled\n"), {})


class Groups(unittest.TestCase):
    def test_curdle_its_modules_and_runtime_are_its_own_the_loader_kernel_and_libc_the_process(self):
        groups = library_floor.grouped(library_floor.shares_in_report(REPORT))
        self.assertAlmostEqual(groups["own"], (1300 + 100 + 100) / 5600)
        self.assertAlmostEqual(groups["process"], (1100 + 500 + 200) / 5600)
        self.assertAlmostEqual(groups["libraries"], (1400 + 600 + 300) / 5600)

    def test_the_geopackages_stream_is_sqlite_gdal_and_loading_them(self):
        shares = library_floor.shares_in_report(REPORT)
        self.assertAlmostEqual(library_floor.gpkg_share(shares), (1400 + 300 + 200) / 5600)


if __name__ == "__main__":
    unittest.main()
