"""Every installer's sheet of layout.pdf has a key naming what its pieces are made of: for each
page, pdftotext's words hold the IDs labelled there, and each of those pieces' material (from
schedule.csv) is named on that page, with the key's heading. Each key line says how many of its
material the sheet holds ("Red facing brick: 409"): over the set, they add up to schedule.csv's
count of each material, so that a coursed set (no IDs) is checked too, and a coursed page names
every course it says it holds ("courses 51 to 106"). Sheet 1 names every zone of the recipe
([[layout.zones]]), drawn where it lies. A curved wall's sheet 1 sets its arc out (radius,
centre, the offsets from its chord, the joints' taper), and each of its sheets states the radius,
the centre, a unit's chord and the taper. A one-brick wall's backing, counted in quantities.csv,
is counted on sheet 1's legend and, sheet by sheet, behind the pieces each holds; a building's
units are counted by part there too (stretchers, headers, closers, each special).

Usage: drawing_keys.py CURDLE SOURCE_DIR PATTERN...
"""

import collections
import csv
import io
import re
import subprocess
import sys
import tempfile
import tomllib
from pathlib import Path

curdle, source, patterns = sys.argv[1], Path(sys.argv[2]), sys.argv[3:]
failures = []
for pattern in patterns:
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([curdle, "generate", str(source / pattern), "--out", tmp, "--outputs",
                        "layout.pdf,schedule.csv,quantities.csv"], check=True,
                       stdout=subprocess.DEVNULL)
        backing = sum(int(r["count"]) for r in csv.DictReader(io.StringIO(
            Path(tmp, "quantities.csv").read_text(encoding="utf-8-sig"), newline=""))
            if r["element_type"].endswith(", backing"))
        behind = 0
        text = Path(tmp, "schedule.csv").read_text(encoding="utf-8-sig")
        material = {r["element_id"]: r["material"]
                    for r in csv.DictReader(io.StringIO(text, newline=""))}
        ordered = collections.Counter(material.values())
        keyed = collections.Counter()
        pages = int(next(line.split()[-1] for line in subprocess.run(
            ["pdfinfo", str(Path(tmp, "layout.pdf"))], capture_output=True, text=True,
            check=True).stdout.splitlines() if line.startswith("Pages:")))
        zones = tomllib.loads((source / pattern).read_text()).get("layout", {}).get("zones", [])
        first = subprocess.run(["pdftotext", "-f", "1", "-l", "1", str(Path(tmp, "layout.pdf")),
                                "-"], capture_output=True, text=True, check=True).stdout
        for zone in zones:
            if zone["name"] not in first:
                failures.append(f"{pattern} sheet 1: zone {zone['name']} is not drawn")
        building = tomllib.loads((source / pattern).read_text()).get("layout", {}).get(
            "building", {})
        curved = any(isinstance(v, dict) or (len(v) == 3 and v[2] != 0)
                     for v in building.get("plan", []) + building.get("path", []))
        flat_first = " ".join(first.split())
        for said in ["setting-out plan of the curved façades", "radius", "centre (",
                     "offsets square to the chord", "mm at the back"] if curved else []:
            if said not in flat_first:
                failures.append(f"{pattern} sheet 1: a curved wall, but no \"{said}\"")
        checked = 0
        for page in range(2, pages + 1):
            words = subprocess.run(["pdftotext", "-f", str(page), "-l", str(page), "-layout",
                                    str(Path(tmp, "layout.pdf")), "-"], capture_output=True,
                                   text=True, check=True).stdout
            if "key: on this sheet" not in words:
                failures.append(f"{pattern} sheet {page}: no key")
                continue
            flat = " ".join(words.split())
            behind += sum(int(n) for n in re.findall(r"behind them, [^:]+: (\d+)", flat))
            if curved and not re.search(r"radius \d+ mm round centre \(.*chord \d+ mm a unit; "
                                        r"joints \d+ mm face, [\d.]+ mm back", flat):
                failures.append(f"{pattern} sheet {page}: a curved wall, its radius, centre, "
                                "chord and taper not stated")
            on_sheet = {material[w] for w in words.split() if w in material}
            for m in on_sheet:
                if m not in flat:
                    failures.append(f"{pattern} sheet {page}: {m} is laid there, not in its key")
            checked += len(on_sheet)
            for m in ordered:
                for n in re.findall(re.escape(m) + r": (\d+)", flat):
                    keyed[m] += int(n)
            courses = re.search(r"courses (\d+) to (\d+)", flat)
            if courses:
                numbers = set(words.split())
                missing = [c for c in range(int(courses[1]), int(courses[2]) + 1)
                           if str(c) not in numbers]
                if missing:
                    failures.append(f"{pattern} sheet {page}: courses {missing[:5]} not numbered")
        # A building's units by part on sheet 1's legend, as schedule.csv types them.
        rows = list(csv.DictReader(io.StringIO(text, newline="")))
        parts = collections.Counter(r["element_type"] for r in rows if r.get("facade"))
        if len(parts) > 1:
            for part, n in parts.items():
                said = re.search(re.escape(f"all tones, {part}: ") + r"(\d+)", flat_first)
                if not said or int(said[1]) != n:
                    failures.append(f"{pattern} sheet 1: {n} of {part} in the schedule, "
                                    f"{said[1] if said else 'none'} on its legend")
        legend = re.search(r"behind the face, [^:]+: (\d+) bricks", " ".join(first.split()))
        if backing and (not legend or int(legend[1]) != backing or behind != backing):
            failures.append(f"{pattern}: quantities.csv counts {backing} backing bricks, sheet 1 "
                            f"{legend[1] if legend else 'none'}, the sheets {behind}")
        if keyed != ordered:
            failures.append(f"{pattern}: the keys count {dict(keyed)}, the schedule "
                            f"{dict(ordered)}")
        print(f"{pattern}: {pages - 1} installer's sheets, {checked} materials found in their keys,"
              f" {sum(keyed.values())} pieces counted in them, {len(zones)} zones named on sheet 1"
              + (", the arc set out" if curved else "")
              + (f", {backing} backing bricks on sheet 1 and behind each sheet's" if backing else "")
              + (f", {len(parts)} parts on sheet 1" if len(parts) > 1 else ""))


def long_names():
    """Material names as real offices write them, over 60 characters: every key line and sheet 1's
    legend wrap the name and keep the count, which add up to the schedule's."""
    names = ["Buff-red multi stock facing brick 215 x 102.5 x 65 mm, frogged, F2 S1",
             "Dark brown engineering brick class B 215 x 102.5 x 65 mm, solid, F2",
             "Red facing brick",
             "Blue engineering brick class A 215 x 102.5 x 65 mm, perforated, F2"]
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([curdle, "generate", str(source / "examples/briefs/brick-facade.toml"),
                        "--set", "layout.materials=" + str(names).replace("'", '"'), "--out", tmp,
                        "--outputs", "layout.pdf,schedule.csv"], check=True,
                       stdout=subprocess.DEVNULL)
        rows = list(csv.DictReader(io.StringIO(
            Path(tmp, "schedule.csv").read_text(encoding="utf-8-sig"), newline="")))
        ordered = collections.Counter(r["material"] for r in rows)
        pdf = str(Path(tmp, "layout.pdf"))
        pages = int(next(line.split()[-1] for line in subprocess.run(
            ["pdfinfo", pdf], capture_output=True, text=True, check=True).stdout.splitlines()
            if line.startswith("Pages:")))
        keyed = collections.Counter()
        for page in range(1, pages + 1):
            # Reading order (not -layout): a name broken over two lines reads as one.
            flat = " ".join(subprocess.run(["pdftotext", "-f", str(page), "-l", str(page), pdf,
                                            "-"], capture_output=True, text=True,
                                           check=True).stdout.split())
            for m in ordered:
                counts = re.findall(re.escape(m) + r": (\d+)", flat)
                if page == 1:
                    if [int(n) for n in counts] != [ordered[m]]:
                        failures.append(f"long names, sheet 1: {m} counted {counts}, the "
                                        f"schedule {ordered[m]}")
                else:
                    keyed[m] += sum(int(n) for n in counts)
        if keyed != ordered:
            failures.append(f"long names: the keys count {dict(keyed)}, the schedule "
                            f"{dict(ordered)}")
        print(f"long names: {pages - 1} installer's sheets keep every count of "
              f"{len(ordered)} materials named in up to {max(map(len, names))} characters")


def north_clear(plan):
    """Sheet 1 of a plan: its north arrow's N overlaps no word of the title block."""
    with tempfile.TemporaryDirectory() as tmp:
        subprocess.run([curdle, "generate", str(source / plan), "--out", tmp, "--outputs",
                        "layout.pdf"], check=True, stdout=subprocess.DEVNULL)
        html = subprocess.run(["pdftotext", "-f", "1", "-l", "1", "-bbox",
                               str(Path(tmp, "layout.pdf")), "-"], capture_output=True,
                              text=True, check=True).stdout
        words = [(float(a), float(b), float(c), float(d), w) for a, b, c, d, w in re.findall(
            r'<word xMin="([\d.]+)" yMin="([\d.]+)" xMax="([\d.]+)" yMax="([\d.]+)">([^<]*)'
            r'</word>', html)]
        norths = [w for w in words if w[4] == "N"]
        if not norths:
            failures.append(f"{plan} sheet 1: no north arrow's N")
        for n in norths:
            for w in words:
                if w is not n and w[0] < n[2] and n[0] < w[2] and w[1] < n[3] and n[1] < w[3]:
                    failures.append(f"{plan} sheet 1: the north arrow's N overlaps '{w[4]}'")
        print(f"{plan}: the north arrow's N clear of {len(words) - 1} words on sheet 1")


long_names()
for plan in ["patterns/courtyard-l-shaped.toml", "patterns/paper/fig5a-park.toml",
             "examples/briefs/cafe-park.toml", "examples/briefs/courtyard.toml",
             "examples/briefs/entrance-paving.toml", "patterns/terrace-curved-edge.toml"]:
    north_clear(plan)
for f in failures[:20]:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
