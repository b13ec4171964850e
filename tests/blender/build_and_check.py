"""Run in Blender: examples/blender_layout.py as a user runs it (its own arguments, its main)
for each pattern given, then check_scene.py over the saved scenes, all in one Blender start
(a start takes 2.3 s, five of them most of the test). A failing step exits Blender non-zero
(run with --python-exit-code 1, so that an uncaught exception does too).

    blender -b --factory-startup --python build_and_check.py -- EXAMPLE CHECK_SCENE \
        RECIPE SEED SCENE.blend SCHEDULE.csv [RECIPE SEED SCENE.blend SCHEDULE.csv ...]
"""

import runpy
import sys

args = sys.argv[sys.argv.index("--") + 1:]
example, check_scene, steps = args[0], args[1], args[2:]
if not steps or len(steps) % 4:
    sys.exit("build_and_check: give RECIPE SEED SCENE SCHEDULE, four at a time")
checks = []
for recipe, seed, scene, schedule in zip(steps[::4], steps[1::4], steps[2::4], steps[3::4]):
    sys.argv = ["blender", "--", recipe, "--seed", seed, "--out", scene]
    runpy.run_path(example, run_name="__main__")
    checks += [scene, schedule]
sys.argv = ["blender", "--", *checks]
runpy.run_path(check_scene, run_name="__main__")
