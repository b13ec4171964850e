#!/usr/bin/env python3
"""layout.dxf's text as four CAD and GIS readers read it: names in French, German, Polish,
Greek and Chinese, and an emoji beyond the BMP, in the drawing's title (TEXT) and as layer
names (the materials), must come back letter for letter.

- ezdxf: every layer name and the title;
- GDAL (python3-gdal's OGR DXF driver, with DXF_ENCODING=UTF-8 as docs/hand-over.md says: GDAL reads
  a DXF's strings in its $DWGCODEPAGE whatever its version): every layer and the title;
- FreeCAD (freecadcmd, its own DXF importer): the title, as a text annotation;
- LibreCAD (librecad dxf2pdf): the drawing printed from layout.dxf draws the very same strokes
  as the same drawing written the way LibreCAD has always read (AutoCAD 2000 with \\U+XXXX
  escapes); a title without the emoji, which AutoCAD 2000 cannot escape.
And, so that the check can fail: the same UTF-8 bytes under an AutoCAD 2000 header (read as
Windows-1252) are printed differently.

Usage: dxf_text_readers.py CURDLE SOURCE_DIR   (Debian's python3 with ezdxf and GDAL)"""
import os
import re
import subprocess
import sys
import tempfile
import zlib
from pathlib import Path

import ezdxf
from osgeo import gdal, ogr

curdle, source = sys.argv[1], Path(sys.argv[2])
recipe = source / "patterns" / "fins-facade-rhythm.toml"
SCRIPTS = "Façade — Grès cérame, Straße, Łódź, Ψυχή, 瓦"
EMOJI = "🌳"
# One per value of the recipe; value 0 lays nothing, so it has no layer.
MATERIALS = ["Void", "Grès cérame — Straße", f"Łódź Ψυχή 瓦 {EMOJI}", "Ελληνικά"]
LAID = MATERIALS[1:]
failures = []


def check(ok, message):
    if not ok:
        failures.append(message)
        print("FAIL:", message)


def generate(work, name, materials):
    out = Path(work) / "out"
    subprocess.run([curdle, "generate", str(recipe), "--out", str(out), "--outputs", "layout.dxf",
                    "--set", f"name={name}",
                    "--set", "layout.materials=[" + ", ".join(f'"{m}"' for m in materials) + "]"],
                   check=True, capture_output=True)
    return out / "layout.dxf"


def title_of(texts):
    return next((t for t in texts if " - seed " in t), None)


def ezdxf_reads(path, name):
    doc = ezdxf.readfile(path)
    layers = {layer.dxf.name for layer in doc.layers}
    for m in LAID:
        check(m in layers, f"ezdxf: no layer {m!r} in {sorted(layers)}")
    title = title_of([e.dxf.text for e in doc.modelspace().query("TEXT")])
    check(title and title.startswith(name), f"ezdxf: title {title!r}")


def gdal_reads(path, name):
    gdal.SetConfigOption("DXF_ENCODING", "UTF-8")
    source = ogr.Open(str(path))
    layer = source.GetLayer(0)
    layers, texts = set(), []
    for feature in layer:
        layers.add(feature.GetField("Layer"))
        if feature.GetField("Text"):
            texts.append(feature.GetField("Text"))
    for m in LAID:
        check(m in layers, f"GDAL: no layer {m!r} in {sorted(layers)}")
    title = title_of(texts)
    check(title and title.startswith(name), f"GDAL: title {title!r}")


FREECAD = """
import FreeCAD, Import
FreeCAD.ParamGet("User parameter:BaseApp/Preferences/Mod/Draft").SetBool("dxftext", True)
FreeCAD.newDocument("check")
Import.readDXF({path!r})
with open({out!r}, "w", encoding="utf-8") as out:
    for o in FreeCAD.ActiveDocument.Objects:
        if hasattr(o, "LabelText"):
            out.write("\\n".join(o.LabelText) + "\\n")
"""


def freecad_reads(path, name, work):
    script, out = Path(work) / "freecad_check.py", Path(work) / "freecad_texts.txt"
    script.write_text(FREECAD.format(path=str(path), out=str(out)), encoding="utf-8")
    run = subprocess.run(["freecadcmd", str(script)], capture_output=True, text=True, errors="replace")
    check(out.exists(), f"FreeCAD: no texts read ({run.stdout[-300:]} {run.stderr[-300:]})")
    if out.exists():
        title = title_of(out.read_text(encoding="utf-8").split("\n"))
        check(title and title.startswith(name), f"FreeCAD: title {title!r}")


def escaped_r2000(text):
    """The drawing as AutoCAD 2000 writes it: every letter beyond ASCII as \\U+XXXX."""
    return "".join(c if ord(c) < 0x80 else f"\\U+{ord(c):04X}" for c in text).replace("AC1021", "AC1015", 1)


def printed(path, work):
    """The strokes LibreCAD prints for a DXF: its PDF's page contents, inflated."""
    env = dict(os.environ, QT_QPA_PLATFORM="offscreen", XDG_RUNTIME_DIR=str(work))
    subprocess.run(["librecad", "dxf2pdf", "-a", str(path)], env=env, capture_output=True, timeout=120)
    pdf = Path(path).with_suffix(".pdf")
    check(pdf.exists(), f"LibreCAD printed nothing for {path.name}")
    if not pdf.exists():
        return b""
    streams = re.findall(rb"stream\r?\n(.*?)\r?\nendstream", pdf.read_bytes(), re.S)
    return b"".join(zlib.decompress(s) for s in streams)


def librecad_reads(work):
    path = generate(work, SCRIPTS, [m.replace(f" {EMOJI}", "") for m in MATERIALS])
    text = path.read_text(encoding="utf-8")
    reference, wrong = Path(work) / "reference.dxf", Path(work) / "wrong.dxf"
    reference.write_text(escaped_r2000(text), encoding="ascii")
    wrong.write_bytes(path.read_bytes().replace(b"AC1021", b"AC1015", 1))
    ours, theirs, misread = printed(path, work), printed(reference, work), printed(wrong, work)
    check(ours and ours == theirs, "LibreCAD: layout.dxf prints otherwise than its AutoCAD 2000 twin")
    check(ours != misread, "LibreCAD: UTF-8 read as Windows-1252 prints the same: the check cannot fail")


with tempfile.TemporaryDirectory() as work:
    name = f"{SCRIPTS}, {EMOJI}"
    path = generate(work, name, MATERIALS)
    ezdxf_reads(path, name)
    gdal_reads(path, name)
    freecad_reads(path, name, work)
with tempfile.TemporaryDirectory() as work:
    librecad_reads(work)

if failures:
    print(f"{len(failures)} failures")
    sys.exit(1)
print("dxf text: ezdxf, GDAL, FreeCAD and LibreCAD read French, German, Polish, Greek, Chinese "
      "and an emoji letter for letter")
