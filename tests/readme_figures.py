#!/usr/bin/env python3
"""Every measured figure the README and the manual (docs/) quote (a time, a size in bytes, a
speed ratio) is produced by a named benchmark or test in the repository: the paragraph, list
item or table row that quotes it,
or else the section it stands in, names a benchmark (tests/benchmarks/..., BM_...), a test
(Suite.Name, or a tests/ script) or an example program, and each name exists. Lists every figure
with its source; exits 1 naming the figures that have none and the sources that do not exist.

Usage: readme_figures.py SOURCE_DIR [--list]"""
import re
import sys
from pathlib import Path

root = Path(sys.argv[1])
listing = "--list" in sys.argv


def read_blocks(path):
    """Blocks of one file: a table row, a list item or a paragraph, each with its heading
    (fences skipped)."""
    blocks, current, heading, fenced = [], None, "", False
    name = path.relative_to(root).as_posix()
    for number, line in enumerate(path.read_text(encoding="utf-8").split("\n"), 1):
        if line.startswith("```"):
            fenced, current = not fenced, None
            continue
        if fenced:
            continue
        if line.startswith("#"):
            heading, current = line.lstrip("# "), None
            continue
        if not line.strip():
            current = None
            continue
        if line.startswith("|") or re.match(r"\s*([-*]|\d+\.) ", line) or current is None:
            current = {"file": name, "line": number, "text": line, "heading": (name, heading)}
            blocks.append(current)
            if line.startswith("|"):
                current = None
            continue
        current["text"] += " " + line
    return blocks


blocks = [b for path in [root / "README.md", *sorted((root / "docs").glob("*.md"))]
          for b in read_blocks(path)]

NUMBER = r"\d[\d,.]*(?:\s?[–-]\s?\d[\d,.]*)?"
# A time, a size or a ratio: "0.23–0.26 s", "13.5 MB", "229–237×"; not a size in cells or
# millimetres ("256 × 256") and not a stage count.
FIGURE = re.compile(rf"(?<![\w.^])({NUMBER})\s?(ms|s|seconds|minutes|MB|GB|kB|KB|×|x)(?![\w/])"
                    r"(?!\s?\d)")
SOURCE = re.compile(r"tests/benchmarks/[\w./-]+|tests/[\w/-]+\.(?:sh|py|mjs|cpp)|examples/[\w/-]+\.(?:py|cpp)"
                    r"|\bBM_\w+|\b[A-Z]\w+\.[A-Z]\w+")


def figures(text):
    text = re.sub(r"`[^`]*`", "", text)  # commands and keys quoted as code are not figures
    found = []
    for m in FIGURE.finditer(text):
        if m.group(2) in ("x", "×") and not re.search(r"\d\s?[–-]|\.\d", m.group(1)) and \
                not re.search(r"(speed|faster|slower|ratio|peer|≥|<|>)", text[max(0, m.start() - 60):m.end() + 20]):
            continue  # "20 ×" a magnification, not a measured ratio
        found.append(m.group(0))
    return found


def exists(source):
    if source.startswith(("tests/", "examples/")):
        return (root / source.rstrip(".,;:)")).exists()
    benches = "".join(p.read_text() for p in (root / "tests/benchmarks").glob("*.cpp"))
    if source.startswith("BM_"):
        return source in benches
    suite, name = source.split(".", 1)
    tests = "".join(p.read_text() for p in (root / "tests").glob("*.cpp"))
    return re.search(rf"TEST(_F|_P)?\(\w*{re.escape(suite)}\w*, {re.escape(name)}", tests) is not None


section_sources = {}
for b in blocks:
    section_sources.setdefault(b["heading"], []).extend(SOURCE.findall(b["text"]))
missing, unknown, listed = [], set(), 0
for b in blocks:
    found = figures(b["text"])
    if not found:
        continue
    own = [s for s in SOURCE.findall(b["text"]) if exists(s)]
    sources = own or [s for s in section_sources[b["heading"]] if exists(s)]
    unknown.update(s for s in SOURCE.findall(b["text"]) if not exists(s) and "/" in s)
    if not sources:
        missing.append(f"{b['file']}:{b['line']}: {', '.join(found)}")
    listed += len(found)
    if listing:
        print(f"{b['file']}:{b['line']}: {', '.join(found)} <- {', '.join(dict.fromkeys(sources))}")
for m in missing:
    print("FAIL: no benchmark or test names this figure:", m)
for u in sorted(unknown):
    print("FAIL: the README or docs/ name a source that does not exist:", u)
print(f"{listed} figures, {len(missing)} without a source")
sys.exit(1 if missing or unknown else 0)
