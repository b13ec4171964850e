"""The Python module against processes, as a designer's script would use either: 1,000 runs of
the paper's fig. 7 (64 x 64 cells, b = 4, p = 2/3, 1/2, 1/3) by calls to the module, by
`curdle generate` processes (its default outputs, and report.json alone, the least a process
can write), and by the numpy peer (../shared/bench/peer_numpy.py) in this process, the same
curdling and box counts a Python user would write instead.

    PYTHONPATH=build/release/python /usr/bin/python3 tests/benchmarks/python_module.py \
        [BUILD_DIR] [PEER_DIR] [RUNS]

Every way runs RUNS times (1,000: about 45 s, most of it the processes). Prints a table and the
ratios.
"""

import importlib.util
import subprocess
import sys
import tempfile
import time
from pathlib import Path

import numpy as np

import curdle

ROOT = Path(__file__).resolve().parents[2]
BUILD = Path(sys.argv[1]) if len(sys.argv) > 1 else ROOT / "build/release"
PEER = Path(sys.argv[2]) if len(sys.argv) > 2 else ROOT.parent / "shared/bench"
RUNS = int(sys.argv[3]) if len(sys.argv) > 3 else 1000
RECIPE = ROOT / "patterns/paper/fig7-three-stages.toml"


def per_run(seconds, runs):
    return seconds / runs * 1000  # ms


def module_calls(with_report):
    recipe = curdle.Recipe.from_file(RECIPE)
    start = time.perf_counter()
    for seed in range(1, RUNS + 1):
        run = recipe.generate(seed=seed)
        if with_report:
            run.report
    return per_run(time.perf_counter() - start, RUNS)


def processes(*outputs):
    with tempfile.TemporaryDirectory() as tmp:
        command = [str(BUILD / "curdle"), "generate", str(RECIPE), "--out", tmp]
        if outputs:
            command += ["--outputs", ",".join(outputs)]
        start = time.perf_counter()
        for seed in range(1, RUNS + 1):
            subprocess.run(command + ["--seed", str(seed)], stdout=subprocess.DEVNULL, check=True)
        return per_run(time.perf_counter() - start, RUNS)


def peer_calls():
    spec = importlib.util.spec_from_file_location("peer_numpy", PEER / "peer_numpy.py")
    peer = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(peer)
    probabilities = [2 / 3, 1 / 2, 1 / 3]
    start = time.perf_counter()
    for seed in range(1, RUNS + 1):
        mask = peer.curdle(4, 2, probabilities, np.random.default_rng(seed))
        peer.box_counts(mask, 4, 3)
    return per_run(time.perf_counter() - start, RUNS)


def main():
    module_calls(False)  # warm: the first call loads the library's pages
    rows = [
        ("module: recipe.generate(seed)", module_calls(False)),
        ("module: generate + run.report (report.json as dicts)", module_calls(True)),
        ("numpy peer in this process: curdle + box counts", peer_calls()),
        ("process: curdle generate --outputs report.json", processes("report.json")),
        ("process: curdle generate (default outputs)", processes()),
    ]
    print(f"fig. 7 (64 x 64, b = 4, K = 3), {RUNS} runs each")
    for name, ms in rows:
        print(f"  {name:<58} {ms:8.3f} ms a run  {ms * RUNS / 1000:8.2f} s for {RUNS}")
    generate, report, peer, lean, default = (ms for _, ms in rows)
    print(f"module generate / default processes:     {100 * generate / default:6.2f} %")
    print(f"module generate / report.json processes: {100 * generate / lean:6.2f} %")
    print(f"module generate + report / default:      {100 * report / default:6.2f} %")
    print(f"peer / module generate + report:         {peer / report:6.1f} x")


if __name__ == "__main__":
    main()
