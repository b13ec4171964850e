"""The layers of the code as documented, checked against the includes.

Reads the table under "## Layout of the code" (docs/code.md, else README.md): each row a layer,
its folders (in backticks) and what it may include (the names of other layers, or "the core's
`x.h`" for single headers). Then checks every #include of src/ and export/:
- a file includes from its own folder, or from a folder of a layer its row allows;
- no folder of export/ includes another's (each writer stands alone over the layers below);
- the graph of folders has no cycle but the documented pair, recipe and kinds;
- no file outside src/io/ and src/site/ opens a file to read it (reading is IO's and a site's).

Usage: layers_check.py SOURCE_DIR
"""
import re
import sys
from collections import defaultdict
from pathlib import Path

root = Path(sys.argv[1])
doc = next(p for p in (root / "docs" / "code.md", root / "README.md") if p.exists()
           and "## Layout of the code" in p.read_text())
text = doc.read_text().split("## Layout of the code", 1)[1]
rows = [line for line in text.splitlines() if line.startswith("| ") and "---" not in line][1:]
layers = []  # (name, folders, allowed cell)
for row in rows:
    cells = [c.strip() for c in row.strip("|").split("|")]
    if len(cells) < 4:
        break
    folders = [f.rstrip("/") for f in re.findall(r"`([a-z/_]+/)`", cells[1])]
    layers.append((cells[0], folders, cells[3]))
folder_layer = {f: name for name, folders, _ in layers for f in folders}
problems = []


def folder_of(path):
    """The documented folder holding a path (the longest that prefixes it)."""
    best = None
    for f in folder_layer:
        if path == f or path.startswith(f + "/"):
            best = f if best is None or len(f) > len(best) else best
    return best


allowed = {}  # layer -> (layers it may include, single headers it may include)
for name, folders, cell in layers:
    headers = set()
    for owner, names in re.findall(r"the (\w+)'s ((?:`[\w.]+`(?:,| and| )*)+)", cell):
        owner_folders = [f for n, fs, _ in layers if n == owner for f in fs]
        for h in re.findall(r"`([\w.]+)`", names):
            headers.update(f"{f}/{h}" for f in owner_folders)
    plain = re.sub(r"the (\w+)'s ((?:`[\w.]+`(?:,| and| )*)+)", "", cell)
    names = {n for n, _, _ in layers if re.search(r"(?<![\w-])" + re.escape(n) + r"(?![\w-])", plain)}
    allowed[name] = (names, headers)

graph = defaultdict(set)
source_files = [p for d in ("src", "export") for p in (root / d).rglob("*")
                if p.suffix in (".h", ".cpp")]
for path in source_files:
    rel = path.relative_to(root).as_posix()
    own = folder_of(rel)
    if own is None:
        problems.append(f"{rel}: in no folder of the table")
        continue
    layer = folder_layer[own]
    body = path.read_text()
    for inc in re.findall(r'#include [<"]([\w/]+\.h)[>"]', body):
        target = inc if inc.startswith("export/") else "src/" + inc
        folder = folder_of(target)
        if folder is None or folder == own:
            continue  # a library's header, or the file's own folder
        graph[own].add(folder)
        names, headers = allowed[layer]
        if folder_layer[folder] in names or target in headers:
            if own.startswith("export/") and folder.startswith("export/"):
                problems.append(f"{rel}: includes {inc}, another writer's folder")
            continue
        problems.append(f"{rel}: includes {inc}; the {layer} layer may include "
                        f"{', '.join(sorted(names)) or 'none'}")
    reads = re.search(r"std::ifstream|std::fstream|\bfopen\(|\bopen\([^)]*O_RDONLY", body)
    if reads and not (own.startswith("src/io") or own.startswith("src/site")):
        problems.append(f"{rel}: opens a file to read it ({reads.group(0)}); reading is src/io's")

# Cycles among folders, but the documented pair.
pair = {("src/recipe", "src/kinds"), ("src/kinds", "src/recipe")}


def cycle_from(start):
    stack, seen = [(start, [start])], set()
    while stack:
        node, path = stack.pop()
        for nxt in graph[node]:
            if (node, nxt) in pair:
                continue
            if nxt == start:
                return path + [nxt]
            if nxt not in seen:
                seen.add(nxt)
                stack.append((nxt, path + [nxt]))
    return None


for folder in sorted(graph):
    if (c := cycle_from(folder)):
        problems.append("a cycle of folders: " + " -> ".join(c))
        break

for p in problems:
    print(p)
print(f"{len(source_files)} files of {len(folder_layer)} folders in {len(layers)} layers "
      f"({doc.relative_to(root)}): {len(problems)} problems")
sys.exit(1 if problems else 0)
