"""The Python module against the command line: for four patterns (a curved-edge paving, a
perforated sheet, a park, a 3-D stack) the module's values equal cells.csv, its report equals
report.json, its elements equal schedule.csv row for row, and every output's bytes equal the
file `curdle generate` writes. Then errors, overrides, windows, search, measure, fit, the GIL
and Ctrl-C.

Usage: module_test.py CURDLE_PROGRAM SOURCE_DIR   (with the module on PYTHONPATH)
"""

import csv
import decimal
import fractions
import io
import json
import math
import os
import signal
import subprocess
import sys
import tempfile
import textwrap
import tomllib
import unittest
from pathlib import Path

import numpy as np

import curdle

PROGRAM = sys.argv[1]
SOURCE = Path(sys.argv[2])
PATTERNS = ["patterns/terrace-curved-edge.toml", "patterns/paper/fig4-perforation.toml",
            "patterns/paper/fig5a-park.toml", "patterns/stacked-blocks.toml",
            "patterns/paving-three-tone-markov.toml"]
SEED = 11
def outputs_for(pattern):
    """Every output the pattern's layout kind takes (parks add their schedules)."""
    kind = tomllib.loads((SOURCE / pattern).read_text()).get("layout", {}).get("kind")
    return [o["name"] for o in curdle.outputs()
            if o["for_kind"] in (None, kind) and not o["for_site_drawing"]]


def cli_generate(pattern, out, *extra):
    subprocess.run([PROGRAM, "generate", str(SOURCE / pattern), "--out", str(out), "--seed",
                    str(SEED), "--outputs", ",".join(outputs_for(pattern)), "--threads", "2",
                    *extra], check=True, stdout=subprocess.DEVNULL)


def read_csv(path):
    text = Path(path).read_text(encoding="utf-8-sig")
    return list(csv.DictReader(io.StringIO(text, newline="")))


def same_mm(csv_text, value):
    """A CSV length (to the micrometre) against the module's unrounded one."""
    if csv_text == "":
        return value is None
    return value is not None and abs(float(csv_text) - value) <= 0.0005 + 1e-9


class AgainstTheCommandLine(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.tmp = tempfile.TemporaryDirectory()
        cls.runs = {}
        for pattern in PATTERNS:
            out = Path(cls.tmp.name) / Path(pattern).stem
            cli_generate(pattern, out)
            run = curdle.Recipe.from_file(SOURCE / pattern).generate(seed=SEED, threads=1)
            cls.runs[pattern] = (run, out)

    @classmethod
    def tearDownClass(cls):
        cls.tmp.cleanup()

    def test_values_equal_cells_csv(self):
        for pattern, (run, out) in self.runs.items():
            rows = read_csv(out / "cells.csv")
            axes = [a for a in ("x", "y", "z") if a in rows[0]]
            values = run.values
            self.assertEqual(values.ndim, len(axes), pattern)
            self.assertEqual(values.size, len(rows), pattern)
            origin = run.origin
            for r in rows:
                at = tuple(int(r[a]) - origin[i] for i, a in enumerate(axes))[::-1]
                self.assertEqual(values[at], int(r["value"]), (pattern, r))
                for name in run.curd_names:
                    if name in run.curd_states:  # a Markov curd's column names the state
                        state = run.curd_states[name][run.states(name)[at]]
                        self.assertEqual(state, r[name], (pattern, name))
                    else:
                        self.assertEqual(run.curd(name)[at], r[name] == "1", (pattern, name))

    def test_report_equals_report_json(self):
        for pattern, (run, out) in self.runs.items():
            self.assertEqual(run.report, json.loads((out / "report.json").read_text()), pattern)

    def test_elements_equal_schedule_csv_row_for_row(self):
        lengths = ["x_mm", "y_mm", "z_mm", "width_mm", "height_mm", "depth_mm",
                   "stock_width_mm", "stock_height_mm"]
        for pattern, (run, out) in self.runs.items():
            rows = read_csv(out / "schedule.csv")
            elements = run.layout.elements
            table = run.layout.table()
            self.assertEqual(len(elements), len(rows), pattern)
            self.assertEqual(len(table), len(rows), pattern)
            for e, t, r in zip(elements, table, rows):
                where = (pattern, r["element_id"])
                for key in ("element_id", "lot", "element_type", "colour", "material",
                            "shape_wkt"):
                    self.assertEqual(getattr(e, key), r[key], where)
                    self.assertEqual(str(t[key]), r[key], where)
                self.assertEqual(e.level, int(r["level"]) if r["level"] else None, where)
                self.assertEqual((e.row, e.column, e.value, e.cut),
                                 (int(r["row"]), int(r["column"]), int(r["value"]),
                                  r["cut"] == "1"), where)
                for key in lengths:
                    self.assertTrue(same_mm(r[key], getattr(e, key)), (where, key))
                    self.assertTrue(same_mm(r[key], None if math.isnan(t[key]) else t[key]),
                                    (where, key))
                self.assertEqual(f"{e.area_m2:.6f}", r["area_m2"], where)
                for name in run.curd_names:
                    # schedule.csv names a Markov curd's state; the element and table number it.
                    cell = r[name] if name not in run.curd_states else \
                        str(run.curd_states[name].index(r[name]))
                    self.assertEqual(e.curds[name], int(cell), where)
                    self.assertEqual(int(t[name]), int(cell), where)
                centre = (r["opening_x_mm"], r["opening_y_mm"], r["opening_diameter_mm"])
                if centre[0]:
                    for text, value in zip(centre, e.opening):
                        self.assertTrue(same_mm(text, value), where)
                else:
                    self.assertIsNone(e.opening, where)
                self.assertEqual(e.polygon is not None, r["shape_wkt"] != "", where)

    def test_every_outputs_bytes_equal_the_command_lines(self):
        for pattern, (run, out) in self.runs.items():
            files = sorted(p.relative_to(out).as_posix() for p in out.rglob("*") if p.is_file())
            self.assertIn("layout.bin", files)
            for name in files:
                self.assertEqual(run.output_bytes(name), (out / name).read_bytes(),
                                 (pattern, name))

    def test_write_gives_the_same_files(self):
        run, out = self.runs[PATTERNS[1]]
        with tempfile.TemporaryDirectory() as tmp:
            written = run.write(outputs_for(PATTERNS[1]), out=Path(tmp) / "screen")
            self.assertTrue(any("sheets" in w for w in written), written)
            for path in written:
                name = Path(path).relative_to(Path(tmp) / "screen").as_posix()
                self.assertEqual(Path(path).read_bytes(), (out / name).read_bytes(), name)


class ABuilding(unittest.TestCase):
    def test_elements_carry_their_facade_and_strip_place_as_schedule_csv(self):
        """A building's pieces say their façade and where they lie on the unrolled strip, as
        schedule.csv does, in the elements and in the table (its façade a word field)."""
        pattern = "patterns/pavilion-l-shaped.toml"
        with tempfile.TemporaryDirectory() as tmp:
            subprocess.run([PROGRAM, "generate", str(SOURCE / pattern), "--out", tmp, "--seed",
                            str(SEED), "--outputs", "schedule.csv"], check=True,
                           stdout=subprocess.DEVNULL)
            rows = read_csv(Path(tmp) / "schedule.csv")
        run = curdle.Recipe.from_file(SOURCE / pattern).generate(seed=SEED, threads=1)
        elements, table = run.layout.elements, run.layout.table()
        self.assertEqual(len(elements), len(rows))
        self.assertEqual(table.dtype["facade"].kind, "U")
        for e, t, r in zip(elements, table, rows):
            self.assertEqual((e.facade, str(t.facade)), (r["facade"], r["facade"]), e.element_id)
            self.assertTrue(same_mm(r["strip_x_mm"], e.strip_x_mm), e.element_id)
            self.assertTrue(same_mm(r["strip_y_mm"], e.strip_y_mm), e.element_id)
        self.assertEqual(sorted({e.facade for e in elements}), ["E", "E2", "N", "N2", "S", "W"])
        plain = curdle.Recipe.from_file(SOURCE / PATTERNS[0]).generate(seed=SEED, threads=1)
        self.assertIsNone(plain.layout.elements[0].facade)
        self.assertIsNone(plain.layout.elements[0].strip_x_mm)


class TheManualsExample(unittest.TestCase):
    def test_library_md_python_block_runs_as_written_and_passes_mypy_strict(self):
        text = (SOURCE / "docs/library.md").read_text(encoding="utf-8")
        block = text.split("```python\n", 1)[1].split("```", 1)[0]
        with tempfile.TemporaryDirectory() as tmp:
            os.symlink(SOURCE / "patterns", Path(tmp) / "patterns")
            (Path(tmp) / "example.py").write_text(block, encoding="utf-8")
            here = os.getcwd()
            os.chdir(tmp)
            try:
                exec(compile(block, "docs/library.md", "exec"), {})
            finally:
                os.chdir(here)
            self.assertTrue((Path(tmp) / "out/courtyard/layout.pdf").is_file())
            # Typed as the package says: mypy --strict finds nothing to fix in the example.
            mypy = subprocess.run(["/usr/bin/python3", "-m", "mypy", "--version"],
                                  capture_output=True)
            if mypy.returncode != 0:
                self.skipTest("mypy is not installed")
            module_dir = Path(curdle.__file__).parent.parent
            checked = subprocess.run(
                ["/usr/bin/python3", "-m", "mypy", "--strict", "--no-incremental",
                 "--cache-dir", str(Path(tmp) / ".mypy"), str(Path(tmp) / "example.py")],
                capture_output=True, text=True, env={**os.environ, "MYPYPATH": str(module_dir)})
            self.assertEqual(checked.returncode, 0, checked.stdout + checked.stderr)


class Calls(unittest.TestCase):
    def test_overrides_seed_and_window_are_the_command_lines(self):
        recipe = curdle.Recipe.from_file(SOURCE / "patterns/paper/fig7-three-stages.toml")
        run = recipe.generate(seed=5, window=(10, 13, 40, 30),
                              overrides={"curds.0.probabilities": ["3/4", "1/2", "1/2"]})
        self.assertEqual(run.values.shape, (30, 40))
        self.assertEqual(run.origin, (10, 13))
        with tempfile.TemporaryDirectory() as tmp:
            subprocess.run([PROGRAM, "generate", recipe.path, "--out", tmp, "--seed", "5",
                            "--window", "10,13,40,30", "--set",
                            'curds.0.probabilities=["3/4", "1/2", "1/2"]', "--outputs",
                            "report.json,cells.csv"], check=True, stdout=subprocess.DEVNULL)
            self.assertEqual(run.output_bytes("cells.csv"),
                             (Path(tmp) / "cells.csv").read_bytes())
        self.assertFalse(run.values.flags.writeable)
        self.assertIsNone(run.layout)

    def test_probabilities_as_python_numbers_and_documented_calls(self):
        # A Fraction stays exact, as "1/5" in the recipe; ints, floats and Decimals are taken.
        run = curdle.generate(SOURCE / "patterns/paper/fig3-two-curds.toml", overrides={
            "curds.0.probabilities": [fractions.Fraction(1, 5), 0.5],
            "curds.1.probabilities": [1, decimal.Decimal("0.25")]})
        texts = [[s["probability_text"] for s in c["stages"]] for c in run.report["curds"]]
        self.assertEqual(texts, [["1/5", "0.5"], ["1", "0.25"]])
        with self.assertRaises(curdle.InputError):
            curdle.generate(SOURCE / "patterns/paper/fig3-two-curds.toml",
                            overrides={"curds.0.probabilities": [decimal.Decimal("NaN"), 1]})
        # Every public name has its help: functions and methods their parameters (when they
        # take any), what they return and raise, and an example; properties and classes a line.
        for name in curdle.__all__:
            thing = getattr(curdle, name)
            members = [(name, thing)]
            if isinstance(thing, type):
                members += [(f"{name}.{k}", v) for k, v in vars(thing).items()
                            if not k.startswith("_") and (callable(v) or isinstance(
                                v, (property, classmethod, staticmethod)))]
            for label, member in members:
                if isinstance(member, (classmethod, staticmethod)):
                    member = member.__func__
                doc = member.__doc__ or ""
                self.assertTrue(len(doc) > 20, label)
                if callable(member) and not isinstance(member, type):
                    for section in ("Returns:", "Raises:", "Example:"):
                        self.assertIn(section, doc, label)
                    if member.__code__.co_argcount > (1 if "." in member.__qualname__ else 0):
                        self.assertIn("Parameters:", doc, label)
        self.assertIn("Fraction", curdle.Recipe.generate.__doc__)
        self.assertEqual(curdle.generate.__annotations__["return"], "Run")

    def test_reprs_say_what_each_is_and_broken_toml_is_refused_at_once(self):
        recipe = curdle.Recipe.from_file(SOURCE / "patterns/paper/fig3-two-curds.toml")
        run = recipe.generate(seed=3)
        for thing, words in ((recipe, ["fig3-two-curds.toml", "lines"]),
                             (run, ["seed=3", "curds=", "cells 16 x 16"]),
                             (run.layout, [run.layout.kind, " mm, ", "tiles"])):
            text = repr(thing)
            self.assertNotIn("\n", text)
            self.assertLess(len(text), 200, text)
            for word in words:
                self.assertIn(word, text)
        self.assertNotIn("[lattice]", repr(recipe))  # not its whole TOML
        with self.assertRaises(curdle.InputError) as caught:
            curdle.Recipe.from_text('name = "x"\n[lattice\nbase = 2\n', "broken.toml")
        self.assertIn("broken.toml:2", str(caught.exception))
        for name in ("seed", "name", "curd_names"):
            self.assertTrue(getattr(curdle.Run, name).__doc__, name)

    def test_bad_input_raises_the_command_lines_message(self):
        bad = "name = \"x\"\n[lattice]\nbase = 1\ndimension = 2\n"
        with tempfile.TemporaryDirectory() as tmp:
            path = Path(tmp) / "bad.toml"
            path.write_text(bad)
            cli = subprocess.run([PROGRAM, "generate", str(path), "--out", tmp],
                                 capture_output=True, text=True)
            self.assertEqual(cli.returncode, 2)
            with self.assertRaises(curdle.InputError) as caught:
                curdle.generate(path)
            self.assertEqual("curdle: error: " + str(caught.exception), cli.stderr.strip())
            self.assertEqual((caught.exception.line, caught.exception.key), (3, "lattice.base"))
        recipe = curdle.Recipe.from_file(SOURCE / "patterns/courtyard-l-shaped.toml")
        cases = [({"overrides": {"lattice.base": 1}}, "overrides lattice.base: must be"),
                 ({"overrides": {"lattice.base": object()}}, "not a recipe value"),
                 ({"seed": 1.5}, "seed: must be a whole number"),
                 ({"window": (0, 0, 99999, 5)}, "window"),
                 ({"max_memory": 1000}, "memory limit")]
        for kwargs, words in cases:
            with self.assertRaises(curdle.InputError, msg=kwargs) as caught:
                recipe.generate(**kwargs)
            self.assertIn(words, str(caught.exception))
        with self.assertRaises(curdle.ResourceLimitError):
            recipe.generate(max_memory=1000)
        with self.assertRaises(curdle.InputError) as caught:
            recipe.generate().output_bytes("layout.txt")
        self.assertIn("allowed: report.json", str(caught.exception))
        with self.assertRaises(curdle.InputError):
            curdle.Recipe.from_file(SOURCE / "patterns")  # a directory, not a recipe

    def test_hostile_calls_raise_and_never_crash(self):
        # A run that is None: a TypeError from every native entry, never a null run read.
        native = curdle._curdle
        for call in (lambda: curdle.Run(None, None).write(out="never"),
                     lambda: native.write(None, [], "never"),
                     lambda: native.GeneratedRun.output_bytes(None, "report.json")):
            with self.assertRaises(TypeError):
                call()
        self.assertFalse(os.path.exists("never"))
        # A key of 60,000 parts (under the 1 MiB a recipe may have): refused, not a stack overflow.
        deep = "a" + ".a" * 60000
        base = (SOURCE / "patterns/paper/fig3-two-curds.toml").read_text()
        for text in (base + deep + " = 1\n", base + "[" + deep + "]\n"):
            with self.assertRaises(curdle.InputError) as caught:
                curdle.Recipe.from_text(text, "deep.toml").generate()
            self.assertIn("at most 64", str(caught.exception))
        recipe = curdle.Recipe.from_file(SOURCE / "patterns/paper/fig3-two-curds.toml")
        with self.assertRaises(curdle.InputError):
            recipe.generate(overrides={deep: 1})
        # A line break in an override's key or value cannot smuggle in a second key.
        for overrides in ({'name="x"\nseed': 5}, {"name": '"x"\nseed = 5'}):
            with self.assertRaises(curdle.InputError, msg=overrides):
                recipe.generate(overrides=overrides)

    def test_two_threads_writing_one_directory_lose_nothing_silently(self):
        import threading
        recipe = curdle.Recipe.from_file(SOURCE / "patterns/paper/fig7-paving-20m.toml")
        runs = [recipe.generate(seed=s) for s in (1, 2)]
        outputs = ["report.json", "cells.csv", "preview.png", "layout.svg", "schedule.csv"]
        with tempfile.TemporaryDirectory() as tmp:
            out = Path(tmp) / "out"
            results = [None, None]
            start = threading.Barrier(2)

            def write(i):
                start.wait()
                try:
                    results[i] = runs[i].write(outputs, out=out)
                except curdle.InputError as e:
                    results[i] = e
            threads = [threading.Thread(target=write, args=(i,)) for i in (0, 1)]
            for t in threads:
                t.start()
            for t in threads:
                t.join()
            # The set in `out` is one run's whole, and a run whose set is not there said so.
            seed = json.loads((out / "report.json").read_text())["seed"]
            self.assertEqual(sorted(p.name for p in out.iterdir()), sorted(outputs))
            kept = [i for i in (0, 1) if runs[i].seed == seed][0]
            self.assertIsInstance(results[kept], list)
            other = results[1 - kept]
            if isinstance(other, list):  # it finished first, and was then replaced whole
                pass
            else:
                self.assertIn("another run wrote", str(other))
            self.assertEqual([p.name for p in Path(tmp).iterdir()], ["out"])  # no staging left

    def test_search_measure_and_fit(self):
        recipe = curdle.Recipe.from_file(SOURCE / "patterns/paper/fig7-three-stages.toml")
        hits = curdle.search(recipe, seeds=range(1, 41), targets=["ratio=0.12"], top=3)
        self.assertEqual([h["rank"] for h in hits["hits"]], [1, 2, 3])
        with tempfile.TemporaryDirectory() as tmp:
            subprocess.run([PROGRAM, "search", recipe.path, "--seeds", "1..40", "--target",
                            "ratio=0.12", "--top", "3", "--out", tmp, "--no-previews"],
                           check=True, stdout=subprocess.DEVNULL)
            seeds = [r["seed"] for r in read_csv(Path(tmp) / "search.csv")]
        self.assertEqual([h["seed"] for h in hits["hits"]], [int(s) for s in seeds])
        self.assertTrue(all(isinstance(h["seed"], int) for h in hits["hits"]))
        # Its command runs as written; a recipe from text has none, but a call that runs.
        best = hits["hits"][0]
        self.assertIn(str(recipe.path), best["command"])
        ranged = curdle.search(curdle.Recipe.from_text(recipe.text, "made-here.toml"),
                               seeds=range(1, 21), targets=["ratio:dark=0.10..0.14"], top=2)
        self.assertIsNone(ranged["hits"][0]["command"])
        self.assertGreater(ranged["hits"][0]["margin"], 0)  # a range ranks by how far inside
        recipe_from_text = curdle.Recipe.from_text(recipe.text, "made-here.toml")
        again = eval(ranged["hits"][0]["call"], {"recipe": recipe_from_text})
        self.assertEqual(again.seed, ranged["hits"][0]["seed"])
        run = recipe.generate(seed=int(seeds[0]))
        with tempfile.TemporaryDirectory() as tmp:
            run.write(["preview.png", "cells.csv"], out=tmp)
            measured = curdle.measure(Path(tmp) / "preview.png", base=2)
            self.assertIn("values", measured)
            fitted = curdle.fit(Path(tmp) / "cells.csv", base=4, stages=3)
            self.assertEqual(fitted["lattice"], {"base": 4, "dimension": 2, "stages": 3})
            again = curdle.Recipe.from_text(fitted["toml"], "fitted.toml").generate(seed=1)
            self.assertEqual(again.values.shape, run.values.shape)
        # A Markov curd's cells come back as its chain, as `curdle fit` reads them.
        paving = curdle.Recipe.from_file(SOURCE / "patterns/paving-three-tone-markov.toml")
        with tempfile.TemporaryDirectory() as tmp:
            paving.generate(layout=False).write(["cells.csv"], out=tmp)
            chain = curdle.fit(Path(tmp) / "cells.csv", base=4, stages=3, stage_wise=True)
            self.assertTrue(chain["recipe_is_chain"])
            self.assertEqual(chain["chain"]["states"], ["dark", "mid"])
            self.assertEqual(chain["chain"]["supported"], "chain")
            self.assertEqual(len(chain["chain"]["transitions"]), 3)
            entry = chain["chain"]["transitions"][2][1][1]
            self.assertLessEqual(entry["low"], entry["value"])
            self.assertLessEqual(entry["value"], entry["high"])


class MovedBuildTree(unittest.TestCase):
    def test_a_build_tree_moved_elsewhere_finds_its_library_and_modules(self):
        # The module finds libcurdle.so relative to itself, and the image module beside the
        # library, wherever the tree now is.
        package = Path(curdle.__file__).parent
        built = package.parent.parent
        with tempfile.TemporaryDirectory() as moved:
            moved = Path(moved)
            (moved / "python").mkdir()
            subprocess.run(["cp", "-r", str(package), str(moved / "python")], check=True)
            for library in built.glob("libcurdle*.so*"):
                subprocess.run(["cp", "-a", str(library), str(moved)], check=True)
            # A BMP: PNGs are read in process, other formats through the image module.
            script = textwrap.dedent(f"""
                import curdle, pathlib, struct
                run = curdle.generate({str((SOURCE / "patterns/paper/fig3-two-curds.toml").resolve())!r})
                pathlib.Path("p.png").write_bytes(run.output_bytes("preview.png"))
                rows = bytes([0, 0, 0, 255, 255, 255, 0, 0]) * 2  # 2 x 2, 24 bits, rows of 8 bytes
                head = struct.pack("<2sIHHI", b"BM", 54 + len(rows), 0, 0, 54)
                info = struct.pack("<IiiHHIIiiII", 40, 2, 2, 1, 24, 0, len(rows), 2835, 2835, 0, 0)
                pathlib.Path("p.bmp").write_bytes(head + info + rows)
                print(curdle.measure("p.png")["size"], curdle.measure("p.bmp")["size"], curdle.__file__)
                print([l.split()[-1] for l in open("/proc/self/maps") if "curdle_image" in l][0])
            """)
            out = subprocess.run([sys.executable, "-c", script], cwd=moved, text=True,
                                 capture_output=True, env=dict(os.environ, PYTHONPATH=str(moved / "python")))
            self.assertEqual(out.returncode, 0, out.stderr)
            self.assertIn(str(moved / "python" / "curdle"), out.stdout)
            self.assertIn(str(moved / "libcurdle_image.so"), out.stdout)


class Interrupting(unittest.TestCase):
    def test_ctrl_c_stops_a_long_search_and_the_gil_is_free_meanwhile(self):
        child = textwrap.dedent(f"""
            import sys, threading, time, curdle
            recipe = curdle.Recipe.from_file({str(SOURCE / "patterns/courtyard-l-shaped.toml")!r})
            ticks = 0
            def tick():
                global ticks
                while True:
                    ticks += 1
                    time.sleep(0.01)
            threading.Thread(target=tick, daemon=True).start()
            print("started", flush=True)
            try:
                curdle.search(recipe, seeds="1..100000000", targets=["ratio=0.3"], threads=1)
                print("finished")
            except KeyboardInterrupt:
                print("interrupted after", ticks, "ticks", flush=True)
        """)
        process = subprocess.Popen([sys.executable, "-c", child], stdout=subprocess.PIPE,
                                   text=True, env=os.environ)
        self.assertEqual(process.stdout.readline().strip(), "started")
        import time
        time.sleep(1.5)
        process.send_signal(signal.SIGINT)
        # Without the stop the search runs for hours: the bound only catches a hang.
        out, _ = process.communicate(timeout=60)
        self.assertIn("interrupted after", out)
        ticks = int(out.split()[2])
        # Held, the GIL would let it tick once or twice at most; on a machine busy with other
        # tests it may get a tenth of its 150 ticks, so the bound is well below that.
        self.assertGreater(ticks, 5, "the tick thread did not run while the search did")


if __name__ == "__main__":
    unittest.main(argv=[sys.argv[0], "-v"])
