"""A parameter sweep as a computational designer runs it in a notebook: the first stage's
probability of the paper's fig. 7 from 0.3 to 1, each with 20 seeds, printing survivors and box
dimension per stage. One process and no files: each run is a library call of a fraction of a
millisecond, where `curdle generate` in a loop pays a process start and writes files each time.

    PYTHONPATH=build/release/python /usr/bin/python3 examples/notebook.py [RECIPE]

($CURDLE names the program to compare with; else curdle on the PATH, else no comparison.)
"""

import os
import shutil
import statistics
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import curdle

HERE = Path(__file__).resolve().parent
recipe = curdle.Recipe.from_file(sys.argv[1] if len(sys.argv) > 1
                                 else HERE.parent / "patterns/paper/fig7-three-stages.toml")
base = curdle.generate(recipe)
rest = [s["probability_text"] for s in base.report["curds"][0]["stages"][1:]]
seeds = range(1, 21)

print(f"{base.name}: p_1 swept, p_2.. = {', '.join(rest)}, {len(seeds)} seeds each")
print(f"{'p_1':>5} | survivors per stage (mean of seeds)     | box dimension (mean, sd)")
start = time.perf_counter()
runs = 0
for p1 in [0.3, 0.4, 0.5, 0.6, 0.7, 0.8, 0.9, 1.0]:
    survivors, dimensions = [], []
    for seed in seeds:
        run = recipe.generate(seed=seed, overrides={"curds.0.probabilities": [p1, *rest]})
        curd = run.report["curds"][0]
        survivors.append([s["survivors"] for s in curd["stages"]])
        if curd["box_dimension"].get("fit") is not None:
            dimensions.append(curd["box_dimension"]["fit"])
        runs += 1
    means = [statistics.mean(stage) for stage in zip(*survivors)]
    dimension = (f"{statistics.mean(dimensions):.3f} ({statistics.pstdev(dimensions):.3f})"
                 if dimensions else "-")
    print(f"{p1:5.2f} | {'  '.join(f'{m:8.1f}' for m in means):<40} | {dimension}")
library = (time.perf_counter() - start) / runs

# The same run as a process, a few times, for comparison ($CURDLE, or curdle on the PATH).
program = os.environ.get("CURDLE") or shutil.which("curdle")
print(f"\n{runs} runs: {library * 1000:.2f} ms a run in this process", end="")
if program:
    with tempfile.TemporaryDirectory() as tmp:
        start = time.perf_counter()
        for seed in range(1, 6):
            subprocess.run([program, "generate", recipe.path, "--seed", str(seed), "--out", tmp],
                           stdout=subprocess.DEVNULL, check=True)
        process = (time.perf_counter() - start) / 5
    print(f"; `curdle generate` takes {process * 1000:.1f} ms a run "
          f"({process / library:.0f} times as long)")
else:
    print()
