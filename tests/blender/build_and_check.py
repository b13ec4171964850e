"""Run in Blender: examples/blender_layout.py as a user runs it (its own arguments, its main)
for each pattern given, then check_scene.py over the saved scenes, then (with
$CURDLE_MASSING_GLB) export_massing.py's grouped massing model, all in one Blender start
(a start takes 2.3 s, five of them most of the test). A failing step exits Blender non-zero
(run with --python-exit-code 1, so that an uncaught exception does too).

    blender -b --factory-startup --python build_and_check.py -- EXAMPLE CHECK_SCENE \
        RECIPE SEED SCENE.blend SCHEDULE.csv [RECIPE SEED SCENE.blend SCHEDULE.csv ...]
"""

import os
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
# In the same start (check_scene.py ends it): a massing model grouped under a parent, for the
# site reader's test.
if os.environ.get("CURDLE_MASSING_GLB"):
    sys.argv = ["blender", "--", os.environ["CURDLE_MASSING_GLB"]]
    runpy.run_path(os.path.join(os.path.dirname(os.path.abspath(__file__)), "export_massing.py"),
                   run_name="__main__")
sys.argv = ["blender", "--", *checks]
runpy.run_path(check_scene, run_name="__main__")
