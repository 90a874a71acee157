#!/usr/bin/env bash
# Lint: every algorithm file of the twins opens with a comment block in the one header schema
# (docs of the schema: the block's labels below; a header states what it computes, then one line
# per public function or class, then the labelled parts), and no comment under reference/ or gpu/
# carries project history as an issue number.
#
#   scripts/check-headers.sh            check the whole set (ctest: Lint.AlgorithmHeaders)
#   scripts/check-headers.sh FILE...    check only these files (by suffix: .hpp as an algorithm
#                                       header, .comp .glsl .vert .frag as a shader), e.g. a probe
#
# The set:
#   Algorithm headers: every .hpp under reference/{erosion,noise,planet,cave,render}/ and
#     gpu/{erosion,noise,planet,cave,render}/ (subfolders included), except these pure utilities,
#     which compute no algorithm of their own:
#       reference/erosion/droplets.hpp      result types and batch-delta helpers of the droplet eroders
#       reference/noise/lattice_floor.hpp   floor() as an int for the lattice noises
#       gpu/erosion/droplet_host.hpp        dispatch and upload helpers of the droplet hosts
#       gpu/cave/linear_dispatch.hpp        1-D dispatch over a 2-D workgroup grid
#       gpu/noise/fractal_terms_layout.hpp  the C++ layout mirror of GtFractalTerms
#       gpu/noise/perlin_texture.hpp        the GL texture object of the texture noise
#       gpu/render/offscreen_target.hpp     the framebuffer both render twins draw into
#     Their first comment block needs the labels Inputs:, Outputs:, Units:, Throws: and Twin:.
#   Shaders: every .comp, .glsl, .vert and .frag under gpu/shaders/; their first comment block
#     (after an optional #version line) needs Inputs:, Outputs: and Twin:.
#   The first comment block is the run of `//` lines at the top of the file; a label counts when
#     a line of it starts with it (`// Inputs:` ...).
#   Issue numbers: no comment (// or /* */) in a .hpp, .cpp, .h, .comp, .glsl, .vert or .frag file
#     under reference/ or gpu/ may mention "issue <number>" (any case, "issue #N" too): state the
#     fact, not the history.
#
# Prints each offending file and what it lacks, then a summary; exits 1 if any file offends.
set -euo pipefail
cd "$(dirname "$0")/.."

exec python3 - "$@" <<'PYTHON'
import pathlib
import re
import sys

ALGORITHM_DIRS = ["erosion", "noise", "planet", "cave", "render"]
UTILITIES = {
    "reference/erosion/droplets.hpp",
    "reference/noise/lattice_floor.hpp",
    "gpu/erosion/droplet_host.hpp",
    "gpu/cave/linear_dispatch.hpp",
    "gpu/noise/fractal_terms_layout.hpp",
    "gpu/noise/perlin_texture.hpp",
    "gpu/render/offscreen_target.hpp",
}
HEADER_LABELS = ["Inputs:", "Outputs:", "Units:", "Throws:", "Twin:"]
SHADER_LABELS = ["Inputs:", "Outputs:", "Twin:"]
SHADER_SUFFIXES = {".comp", ".glsl", ".vert", ".frag"}
SOURCE_SUFFIXES = {".hpp", ".cpp", ".h"} | SHADER_SUFFIXES
ISSUE = re.compile(r"\bissue\s*#?\s*[0-9]", re.IGNORECASE)


def algorithm_headers():
    for side in ("reference", "gpu"):
        for folder in ALGORITHM_DIRS:
            for path in sorted(pathlib.Path(side, folder).rglob("*.hpp")):
                if path.as_posix() not in UTILITIES:
                    yield path


def shaders():
    return sorted(p for p in pathlib.Path("gpu/shaders").rglob("*") if p.suffix in SHADER_SUFFIXES)


def first_block(text):
    """The lines of the comment block that opens the file (after a #version line)."""
    lines = text.split("\n")
    if lines and lines[0].startswith("#version"):
        lines = lines[1:]
    block = []
    for line in lines:
        if not line.lstrip().startswith("//"):
            break
        block.append(line.lstrip()[2:].strip())
    return block


def missing_labels(path, labels):
    block = first_block(path.read_text(encoding="utf-8", errors="replace"))
    if not block:
        return ["the opening comment block"]
    return [label for label in labels if not any(line.startswith(label) for line in block)]


def comments(text):
    """(line number, comment text) of every // and /* */ comment, outside string literals."""
    found = []
    i, n, line = 0, len(text), 1
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            end = text.find("\n", i)
            end = n if end < 0 else end
            found.append((line, text[i:end]))
            i = end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            end = n if end < 0 else end + 2
            found.append((line, text[i:end].replace("\n", " ")))
            line += text.count("\n", i, end)
            i = end
        elif c in "\"'":
            j = i - 1
            while j >= 0 and (text[j].isalnum() or text[j] == "_"):
                j -= 1
            prefix = text[j + 1:i]
            if c == '"' and prefix in ("R", "u8R", "uR", "UR", "LR"):
                open_paren = text.find("(", i)
                close = text.find(")" + text[i + 1:open_paren] + '"', open_paren)
                end = n if open_paren < 0 or close < 0 else close + open_paren - i + 1
            elif c == "'" and prefix[:1].isdigit():
                end = i + 1  # a digit separator
            else:
                end = i + 1
                while end < n and text[end] not in (c, "\n"):
                    end += 2 if text[end] == "\\" else 1
                end += 1
            line += text.count("\n", i, min(end, n))
            i = end
        else:
            if c == "\n":
                line += 1
            i += 1
    return found


def issue_mentions(path):
    text = path.read_text(encoding="utf-8", errors="replace")
    return [(number, comment.strip()) for number, comment in comments(text) if ISSUE.search(comment)]


arguments = [pathlib.Path(argument) for argument in sys.argv[1:]]
if arguments:
    headers = [p for p in arguments if p.suffix == ".hpp"]
    shader_files = [p for p in arguments if p.suffix in SHADER_SUFFIXES]
    scanned = [p for p in arguments if p.suffix in SOURCE_SUFFIXES]
else:
    headers = list(algorithm_headers())
    shader_files = shaders()
    scanned = sorted(p for side in ("reference", "gpu") for p in pathlib.Path(side).rglob("*")
                     if p.suffix in SOURCE_SUFFIXES)

problems = {}
for path in headers:
    lacking = missing_labels(path, HEADER_LABELS)
    if lacking:
        problems.setdefault(path.as_posix(), []).append("lacks " + ", ".join(lacking))
for path in shader_files:
    lacking = missing_labels(path, SHADER_LABELS)
    if lacking:
        problems.setdefault(path.as_posix(), []).append("lacks " + ", ".join(lacking))
for path in scanned:
    for number, comment in issue_mentions(path):
        problems.setdefault(path.as_posix(), []).append(f"line {number} mentions an issue number: {comment[:80]}")

for path in sorted(problems):
    for problem in problems[path]:
        print(f"{path}: {problem}")
checked = len({p.as_posix() for p in headers + shader_files + scanned})
print(f"check-headers: {len(headers)} algorithm headers and {len(shader_files)} shaders checked for the schema, "
      f"{len(scanned)} files for issue numbers; {len(problems)} of {checked} files offend")
sys.exit(1 if problems else 0)
PYTHON
