"""The five design briefs of examples/briefs, each done as the manual (docs/briefs.md) tells a new user, and each
checked for what its user needs from it:

- courtyard: its DXF names the porcelain ("Grès cérame") right when ezdxf reads it back, and
  ezdxf's audit finds nothing; the planter is on the ZONES layer, not OPENINGS;
- brick façade: the installer's set is at most 40 A3 sheets, coursed (no IDs; each sheet says
  which courses it holds and how to read it); sheet 1 sets out the wall and every opening from
  the datum;
- gabled screen: a search for sheet_open_area=0.25..0.35 finds a seed, and every fabrication
  sheet of that seed (punching.csv) is 25-35 % open;
- entrance paving: the segment the search chose keeps the entrance clear of dark setts, and the
  title block names the window;
- café park: planting.csv holds every tree of the schedule, by species, sizes, pit and centre, and the
  furniture and surfaces schedules are written.

Usage: briefs.py CURDLE SOURCE_DIR (Debian's python3 with python3-ezdxf; poppler-utils)
"""

import csv
import io
import re
import subprocess
import sys
import tempfile
from pathlib import Path

import ezdxf

curdle, source = sys.argv[1], Path(sys.argv[2])
briefs = source / "examples" / "briefs"
failures = []


def run(*args):
    return subprocess.run([curdle, *args], check=True, capture_output=True, text=True).stdout


def rows(path):
    return list(csv.DictReader(io.StringIO(Path(path).read_text(encoding="utf-8-sig"), newline="")))


def pdf_text(path, page=None):
    pages = ["-f", str(page), "-l", str(page)] if page else []
    return subprocess.run(["pdftotext", *pages, str(path), "-"], capture_output=True, text=True,
                          check=True).stdout


def pages(path):
    info = subprocess.run(["pdfinfo", str(path)], capture_output=True, text=True, check=True)
    fields = dict(line.split(":", 1) for line in info.stdout.splitlines() if ":" in line)
    return int(fields["Pages"]), fields["Page size"]


def check(ok, message):
    if not ok:
        failures.append(message)


with tempfile.TemporaryDirectory() as tmp:
    out = Path(tmp, "courtyard")
    run("generate", str(briefs / "courtyard.toml"), "--out", str(out), "--outputs",
        "layout.dxf,schedule.csv")
    doc = ezdxf.readfile(out / "layout.dxf")
    auditor = doc.audit()
    check(not auditor.errors, f"courtyard: ezdxf's audit found {len(auditor.errors)} errors")
    layers = {layer.dxf.name for layer in doc.layers}
    for material in {r["material"] for r in rows(out / "schedule.csv")}:
        check(material.replace(",", "_") in layers,
              f"courtyard: ezdxf reads no layer {material!r}, only {sorted(layers)}")
    check("ZONES" in layers and "OPENINGS" not in layers,
          f"courtyard: the planter is not on ZONES alone: {sorted(layers)}")
    print(f"courtyard: {len(layers)} layers read back, the porcelain named right")

    out = Path(tmp, "brick")
    run("generate", str(briefs / "brick-facade.toml"), "--out", str(out), "--outputs",
        "layout.pdf")
    count, size = pages(out / "layout.pdf")
    check(count - 1 <= 40, f"brick façade: {count - 1} installer's sheets, more than 40")
    check("A3" in size, f"brick façade: sheets of {size}, not A3")
    for page in range(2, count + 1):
        words = " ".join(pdf_text(out / "layout.pdf", page).split())
        check("in its key's colour and hatch" in words and "courses" in words
              and "F-R" not in words, f"brick façade sheet {page}: not a coursed sheet")
        check(re.search(r"from the datum \(0, 0\): x [0-9]+ to [0-9]+, y [0-9]+ to [0-9]+",
                        words), f"brick façade sheet {page}: not set out from the datum")
    first = pdf_text(out / "layout.pdf", 1).split()
    missing = [v for v in ("0", "15065", "15965", "1350", "4275", "7200", "10125", "13050", "4125",
                           "7350", "10575", "13800", "900", "9000", "11250", "2400", "2700")
               if v not in first]
    check("setting" in first and not missing,
          f"brick façade sheet 1: the windows are not set out from the datum: {missing}")
    print(f"brick façade: {count - 1} coursed installer's sheets on {size.strip()}, the windows "
          f"set out on sheet 1")

    out = Path(tmp, "screen")
    run("search", str(briefs / "gabled-screen.toml"), "--seeds", "1..6", "--target",
        "sheet_open_area=0.25..0.35", "--top", "1", "--out", str(out))
    best = rows(out / "search.csv")[0]
    check(float(best["score"]) == 0, f"gabled screen: no seed of 1..6 met the target: {best}")
    run("generate", str(briefs / "gabled-screen.toml"), "--seed", best["seed"], "--out",
        str(out), "--outputs", "punching.csv")
    sheets = [r for r in rows(out / "punching.csv") if r["sheet_id"] != "total"]
    check(len(sheets) == 8, f"gabled screen: {len(sheets)} sheets, not 8")
    for r in sheets:
        check(0.25 <= float(r["open_share"]) <= 0.35,
              f"gabled screen seed {best['seed']}: {r['sheet_id']} is {r['open_share']} open")
    print(f"gabled screen: seed {best['seed']} has every sheet 25-35 % open: "
          + ", ".join(r["open_share"] for r in sheets))

    out = Path(tmp, "entrance")
    run("generate", str(briefs / "entrance-paving.toml"), "--out", str(out), "--outputs",
        "schedule.csv,layout.pdf")
    inside = [r for r in rows(out / "schedule.csv")
              if 4000 <= float(r["x_mm"]) + float(r["width_mm"]) / 2 <= 6000
              and float(r["y_mm"]) + float(r["height_mm"]) / 2 <= 1600]
    check(len(inside) >= 15 and all(r["value"] == "0" for r in inside),
          f"entrance paving: the entrance holds {len(inside)} setts, "
          f"{sum(r['value'] != '0' for r in inside)} dark")
    check("window 60,27,25,25" in pdf_text(out / "layout.pdf", 1),
          "entrance paving: sheet 1 does not name the window")
    print(f"entrance paving: {len(inside)} setts in the entrance, none dark")

    out = Path(tmp, "park")
    run("generate", str(briefs / "cafe-park.toml"), "--out", str(out), "--outputs",
        "schedule.csv,planting.csv,furniture.csv,surfaces.csv")
    trees = {r["element_id"] for r in rows(out / "schedule.csv")
             if r["element_type"] == "tree"}
    planted = rows(out / "planting.csv")
    check({r["element_id"] for r in planted} == trees and trees,
          f"café park: planting.csv holds {len(planted)} trees, the schedule {len(trees)}")
    check(all(r["species"] == "Tilia cordata 'Greenspire'" and float(r["canopy_diameter_mm"]) == 1200
              and r["girth_cm"] == "18-20" and r["root_ball_mm"] == "600"
              and r["pit_width_mm"] == r["pit_length_mm"] == "1500" for r in planted),
          "café park: a tree is planted without its species, canopy, girth, root ball or pit")
    check(all(float(r["edging_m"]) > 0 for r in rows(out / "surfaces.csv")),
          "café park: a surface without its edging")
    check(rows(out / "furniture.csv") and rows(out / "surfaces.csv"),
          "café park: no furniture or surfaces schedule")
    print(f"café park: {len(planted)} trees in planting.csv")

for f in failures[:20]:
    print("FAIL:", f)
sys.exit(1 if failures else 0)
