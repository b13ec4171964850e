#!/usr/bin/env python3
"""Every pattern's layout.gpkg read back by GDAL (python3-gdal, the library under QGIS and
ogrinfo) beside the schedule.csv written with it: a layer per kind of element, one feature per
schedule row with the same ID, material and area_m2, and its geometry the row's shape_wkt in
metres (shape_wkt is written to the micrometre: extents within 1 µm, areas within a millionth). And one park placed with layout.georef: the layers in
its EPSG code, every piece where the datum, the rotation and its schedule put it.

Usage: gpkg_read_back.py CURDLE SOURCE_DIR [WRITTEN]   (Debian's python3 with GDAL)
WRITTEN: a directory per pattern already written (the cli.pattern tests', with layout.gpkg and
schedule.csv); every other pattern is generated here."""
import csv
import sqlite3
import math
import subprocess
import sys
import tempfile
from pathlib import Path

from osgeo import ogr, osr

ogr.UseExceptions()
curdle, source = sys.argv[1], Path(sys.argv[2])
written_dir = Path(sys.argv[3]) if len(sys.argv) > 3 else None
failures = []


def fail(message):
    failures.append(message)
    if len(failures) <= 20:
        print("FAIL:", message)


def generate(recipe, out, *sets):
    args = [curdle, "generate", str(recipe), "--out", str(out), "--outputs", "layout.gpkg,schedule.csv"]
    for s in sets:
        args += ["--set", s]
    subprocess.run(args, check=True, capture_output=True)
    return schedule(out)


def features(path):
    data = ogr.Open(str(path))
    for i in range(data.GetLayerCount()):
        layer = data.GetLayer(i)
        for feature in layer:
            yield layer, feature


def near(a, b, tolerance=1e-9):
    return abs(a - b) <= tolerance * max(1.0, abs(a), abs(b))


def schedule(out):
    with open(out / "schedule.csv", encoding="utf-8-sig", newline="") as f:
        return {row["element_id"]: row for row in csv.DictReader(f)}


def check_pattern(recipe, work):
    rows = schedule(work) if work.is_dir() else generate(recipe, work)
    # No georef: every layer in the undefined Cartesian SRS (srs_id -1), never the undefined
    # geographic one (0), whose metres GDAL and QGIS read as degrees.
    with sqlite3.connect(work / "layout.gpkg") as db:
        ids = {srs for (srs,) in db.execute("SELECT srs_id FROM gpkg_contents")}
    if ids != {-1}:
        fail(f"{recipe.name}: layers in srs_id {sorted(ids)}, not the undefined Cartesian -1")
    seen, tables = set(), set()
    for layer, feature in features(work / "layout.gpkg"):
        if layer.GetName() not in tables:  # fields by index: a lookup by name per call is slow
            tables.add(layer.GetName())
            defn = layer.GetLayerDefn()
            at = {f: defn.GetFieldIndex(f) for f in ("element_id", "material", "area_m2")}
            # planting.csv's and furniture.csv's columns on every layer (null where they say
            # nothing), and the zone each piece is booked to.
            for f in ("species", "girth_cm", "root_ball_mm", "pit_width_mm", "pit_length_mm",
                      "facing_deg", "zone"):
                if defn.GetFieldIndex(f) < 0:
                    fail(f"{recipe.name}: layer {layer.GetName()} has no field {f}")
        key = feature.GetFieldAsString(at["element_id"])
        row = rows.get(key)
        if row is None:
            fail(f"{recipe.name}: {key} is in no schedule row")
            continue
        seen.add(key)
        material = feature.GetFieldAsString(at["material"])
        if material != row["material"]:
            fail(f"{recipe.name} {key}: material {material!r}, schedule {row['material']!r}")
        area = feature.GetFieldAsDouble(at["area_m2"])
        if not near(area, float(row["area_m2"])):
            fail(f"{recipe.name} {key}: area_m2 {area}, schedule {row['area_m2']}")
        shape = ogr.CreateGeometryFromWkt(row["shape_wkt"])
        geometry = feature.GetGeometryRef()
        if not near(geometry.GetArea(), shape.GetArea() / 1e6, 1e-6):
            fail(f"{recipe.name} {key}: {geometry.GetArea()} m², shape_wkt {shape.GetArea() / 1e6}")
        a, b = geometry.GetEnvelope(), shape.GetEnvelope()
        if any(abs(x - y / 1000) > 1e-6 for x, y in zip(a, b)):
            fail(f"{recipe.name} {key}: extent {a}, shape_wkt's {b} mm")
    if seen != set(rows):
        fail(f"{recipe.name}: {len(rows) - len(seen)} schedule rows have no feature")
    kinds = {row["element_type"] for row in rows.values()}
    if len(tables) != len(kinds):
        fail(f"{recipe.name}: layers {sorted(tables)} for kinds {sorted(kinds)}")
    return len(seen)


def check_georef(work):
    """fig. 5a's park at 500,000 E, 5,700,000 N of ETRS89 / UTM 32N, turned 30°."""
    rows = generate(source / "patterns/paper/fig5a-park.toml", work,
                    "layout.georef={epsg = 25832, easting = 500000, northing = 5700000, rotation = 30}")
    turn = math.radians(30)
    count = 0
    for layer, feature in features(work / "layout.gpkg"):
        srs = layer.GetSpatialRef()
        if srs is None or srs.GetAuthorityCode(None) != "25832":
            fail(f"georef: layer {layer.GetName()} not in EPSG:25832")
            return
        row = rows[feature.GetFieldAsString(feature.GetFieldIndex("element_id"))]
        # A piece's centroid, turned and moved as the georef says, is the feature's.
        shape = ogr.CreateGeometryFromWkt(row["shape_wkt"])
        cx, cy = shape.Centroid().GetX() / 1000, shape.Centroid().GetY() / 1000
        ce = 500000 + cx * math.cos(turn) - cy * math.sin(turn)
        cn = 5700000 + cx * math.sin(turn) + cy * math.cos(turn)
        c = feature.GetGeometryRef().Centroid()
        if abs(c.GetX() - ce) > 1e-5 or abs(c.GetY() - cn) > 1e-5:
            fail(f"georef {row['element_id']}: centroid ({c.GetX()}, {c.GetY()}), expected ({ce}, {cn})")
        count += 1
    if count != len(rows):
        fail(f"georef: {count} features for {len(rows)} rows")


total = 0
patterns = sorted(p for p in (source / "patterns").rglob("*.toml") if "[layout]" in p.read_text(encoding="utf-8"))
with tempfile.TemporaryDirectory() as tmp:
    for i, recipe in enumerate(patterns):
        written = written_dir / recipe.stem if written_dir else None
        total += check_pattern(recipe, written if written and written.is_dir() else Path(tmp) / str(i))
    check_georef(Path(tmp) / "georef")
if failures:
    print(f"{len(failures)} failures")
    sys.exit(1)
print(f"gpkg: {len(patterns)} patterns' {total} pieces read back by GDAL as the schedules give them; "
      "the georeferenced park in EPSG:25832 where its datum and rotation put it")
