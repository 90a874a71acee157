#!/usr/bin/env bash
# Proof that a change touched comments only: for each source file that differs between a git
# revision and the working tree, compare the two versions with their comments and blank lines
# stripped, and name the files whose code differs.
#
#   scripts/comment-only-diff.sh [REV] [-- PATH...]
#
# REV defaults to HEAD; PATHs limit the files compared (e.g. `-- reference gpu`). Compared: tracked
# files that differ from REV (staged or not) and untracked files that git does not ignore, with the
# suffixes .hpp .cpp .h .comp .glsl .vert .frag. A file added or deleted since REV counts as a code
# change when its other side holds any code.
#
# Stripping: `//` comments to the end of the line and `/* */` comments, outside string and
# character literals. Literals are recognised, so a "//" inside a string (e.g. gpu/shader_program.cpp's
# regexes) stays code: plain "..." and '...' with backslash escapes, raw strings R"delim(...)delim"
# (also with u8/u/U/L prefixes), and C++14 digit separators (1'000'000) are not taken for a character
# literal. A removed comment may leave trailing blanks; trailing whitespace is dropped from each line
# and lines left empty are dropped, and nothing else is normalised (indentation and blanks between
# tokens must match). A line splice (backslash-newline) inside a `//` comment is not followed.
#
# Prints "code differs: PATH" for each such file and exits 1 if any; otherwise prints how many files
# were compared and exits 0. Needs bash, git and python3 only.
set -euo pipefail
cd "$(dirname "$0")/.."

rev=HEAD
if [[ $# -gt 0 && $1 != "--" ]]; then
  rev=$1
  shift
fi
if [[ $# -gt 0 && $1 == "--" ]]; then shift; fi
git rev-parse --verify --quiet "$rev^{commit}" >/dev/null || { echo "not a revision: $rev" >&2; exit 2; }

exec python3 - "$rev" "$@" <<'PYTHON'
import subprocess
import sys

rev, paths = sys.argv[1], sys.argv[2:]
suffixes = (".hpp", ".cpp", ".h", ".comp", ".glsl", ".vert", ".frag")


def git(*args):
    return subprocess.run(["git", *args], check=True, capture_output=True).stdout


def token_before(text, i):
    """The identifier or number characters right before position i."""
    j = i
    while j > 0 and (text[j - 1].isalnum() or text[j - 1] in "_."):
        j -= 1
    return text[j:i]


def skip_quoted(text, i, quote):
    """Position after the literal opened by the quote at i (backslash escapes honoured)."""
    i += 1
    while i < len(text) and text[i] != quote and text[i] != "\n":
        i += 2 if text[i] == "\\" else 1
    return i + 1


def strip_comments(text):
    """The text's non-blank lines with comments removed and trailing whitespace dropped."""
    out = []
    i, n = 0, len(text)
    while i < n:
        c = text[i]
        if text.startswith("//", i):
            end = text.find("\n", i)
            i = n if end < 0 else end
        elif text.startswith("/*", i):
            end = text.find("*/", i + 2)
            out.append(" ")  # a comment between tokens separates them
            i = n if end < 0 else end + 2
        elif c == '"':
            start = i
            if token_before(text, i) in ("R", "u8R", "uR", "UR", "LR"):
                open_paren = text.find("(", i)
                delimiter = text[i + 1:open_paren]
                close = text.find(")" + delimiter + '"', open_paren)
                i = n if open_paren < 0 or close < 0 else close + len(delimiter) + 2
            else:
                i = skip_quoted(text, i, '"')
            out.append(text[start:i])
        elif c == "'":
            start = i
            token = token_before(text, i)
            i = i + 1 if token[:1].isdigit() else skip_quoted(text, i, "'")  # digit separator or literal
            out.append(text[start:i])
        else:
            out.append(c)
            i += 1
    lines = (line.rstrip() for line in "".join(out).split("\n"))
    return [line for line in lines if line]


def old_version(path):
    try:
        return git("show", f"{rev}:{path}").decode("utf-8", "replace")
    except subprocess.CalledProcessError:
        return ""  # added since rev


def new_version(path):
    try:
        with open(path, encoding="utf-8", errors="replace") as file:
            return file.read()
    except FileNotFoundError:
        return ""  # deleted since rev


changed = git("diff", "--no-renames", "--name-only", rev, "--", *paths).decode().split("\n")
untracked = git("ls-files", "--others", "--exclude-standard", "--", *paths).decode().split("\n")
files = sorted({path for path in changed + untracked if path.endswith(suffixes)})
differing = [path for path in files if strip_comments(old_version(path)) != strip_comments(new_version(path))]
for path in differing:
    print(f"code differs: {path}")
if differing:
    print(f"{len(differing)} of {len(files)} changed source files differ in code against {rev}")
    sys.exit(1)
print(f"comments only: {len(files)} changed source files, no code change against {rev}")
PYTHON
