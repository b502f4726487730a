#!/bin/sh
# SPDX-License-Identifier: MIT
# The shape of the core (src/): no import circle between its files, by the
# symbols their object files use or by the headers they include; no
# function over 80 lines or of cyclomatic complexity over 20.
#
#   scripts/check_shape.sh [--known FILE] [--cc CC] [ROOT]
#
# Circles by symbols: each src/*.c is compiled (CC, default cc; -O1, the
# default configuration, again with the 32-bit target arithmetic,
# STP_WIDE_ARITH 0, and with STP_SMALL_DIVISION 1) and nm lists what it defines and what it needs; a file
# using a symbol another defines depends on it.
# Circles by includes: a header of src/ stands for the .c files whose
# symbols it names (declares, or calls in its inline code and macros) and,
# by its name, for src/X.c when it is X_private.h; a .c file depends on
# every .c file the headers it includes stand for, directly or through
# other headers (every #include "..." of src/, whatever #if surrounds it).
# A header with no .c of its own that names no function of one (types,
# macros, inline code) is no dependency.  The public headers
# (include/stipple/) are the library's interface and are not counted.
# In either graph every strongly connected group of two or more files is a
# circle.  Each header declares (a declaration starting a line, not static)
# only functions and data of its own .c file (X.c for X_private.h; none for
# a header without one).  Function sizes come from pmccabe (Debian package
# pmccabe): its traditional McCabe complexity and its line count of each
# function.
#
# Every finding is printed as one line (an include circle is followed by
# its edges, each with the headers and symbols that make it):
#   circle a.c b.c ...          (the files of the circle, sorted)
#   include-circle a.c b.c ...
#   declares HEADER FILE.c SYMBOLS   (a header declaring another file's)
#   long FILE FUNCTION LINES
#   complex FILE FUNCTION COMPLEXITY
# With --known FILE (lines "circle a.c b.c", "include-circle a.c b.c",
# "declares HEADER FILE.c", "long FILE FUNCTION", "complex FILE FUNCTION";
# # comments), the known offenders are reported but pass, and the script
# fails only on new ones; a known offender that is gone is reported so the
# list can shrink.  Exit status 0: no new offender; 1: a new one; 2: usage
# or a missing tool.
set -eu
known=
cc=${CC:-cc}
while [ $# -gt 0 ]; do
    case $1 in
    --known) known=$2; shift 2 ;;
    --cc) cc=$2; shift 2 ;;
    -h | --help) sed -n '3,40p' "$0"; exit 0 ;;
    -*) echo "check_shape: unknown option $1" >&2; exit 2 ;;
    *) break ;;
    esac
done
root=${1:-$(dirname "$0")/..}
root=$(cd "$root" && pwd)
for tool in "$cc" nm pmccabe python3; do
    command -v "$tool" >/dev/null 2>&1 || { echo "check_shape: $tool not found (Debian: pmccabe, binutils, python3)" >&2; exit 2; }
done
[ -z "$known" ] || [ -f "$known" ] || { echo "check_shape: no file $known" >&2; exit 2; }
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT

# 1. symbols defined and used by each object file, in three configurations
for src in "$root"/src/*.c; do
    name=$(basename "$src")
    for arith in "" -DSTP_WIDE_ARITH=0 -DSTP_SMALL_DIVISION=1; do
        # shellcheck disable=SC2086 # $arith: one word or none
        "$cc" -std=c99 -O1 $arith -I "$root/include" -I "$root/src" -c "$src" -o "$work/$name.o" ||
            { echo "check_shape: $src does not compile${arith:+ with $arith}" >&2; exit 2; }
        nm --defined-only -g "$work/$name.o" | awk -v f="$name" 'NF >= 3 { print "D", f, $3 }' >>"$work/symbols"
        nm -u "$work/$name.o" | awk -v f="$name" '{ print "U", f, $NF }' >>"$work/symbols"
    done
done

# 2. function sizes
pmccabe "$root"/src/*.c 2>/dev/null | awk '{
    split($6, where, "("); file = where[1]; sub(".*/", "", file)
    if ($5 > 80) print "long", file, $7, $5
    if ($2 > 20) print "complex", file, $7, $2
}' >"$work/findings"

# 3. circles (by symbols and by includes), and the comparison with the
#    known list
python3 - "$work/symbols" "$work/findings" "$known" "$root/src" <<'PY'
import glob, os, re, sys

symbols, findings_file, known_file, src = sys.argv[1:5]
defined, uses = {}, {}
for line in open(symbols):
    kind, f, sym = line.split()
    if kind == "D":
        defined[sym] = f
    else:
        uses.setdefault(f, set()).add(sym)
files = sorted(set(defined.values()) | set(uses))
edges = {f: sorted({defined[s] for s in uses.get(f, ()) if s in defined and defined[s] != f}) for f in files}

# The include graph.  A header of src/ stands for the .c files whose
# symbols it names (declares, or calls in its inline functions and macros)
# and, by name, for src/X.c when it is X_private.h; a .c file depends on
# every .c file its headers stand for, directly or through the headers they
# include (every #include "..." of src/, whatever #if surrounds it).
# Comments are left out; a header naming nothing of any .c (types, macros,
# inline code over other headers) is no dependency.
token = re.compile(r'"(?:\\.|[^"\\\n])*"|\'(?:\\.|[^\'\\\n])*\'|/\*.*?\*/|//[^\n]*', re.S)
text = {}
for path in glob.glob(os.path.join(src, "*.[ch]")):
    with open(path) as f:
        text[os.path.basename(path)] = token.sub(lambda m: m.group(0) if m.group(0)[0] in "\"'" else " ", f.read())
includes = {f: [h for h in re.findall(r'^[ \t]*#[ \t]*include[ \t]*"([^"]+)"', t, re.M) if h in text]
            for f, t in text.items()}
stands_for = {}  # header -> {c file: [why]}
for h, t in text.items():
    if h.endswith(".h"):
        why = {}
        for name in sorted(set(re.findall(r"[A-Za-z_]\w*", t))):
            if name in defined:
                why.setdefault(defined[name], []).append(name)
        own = h[:-len("_private.h")] + ".c" if h.endswith("_private.h") else None
        if own in text:
            why.setdefault(own, []).insert(0, "(its name)")
        stands_for[h] = why
# What each header declares (a declaration starting a line, not static):
# a header declares only its own .c file's functions and data.
declares = re.compile(r"^(?!static\b|typedef\b)[A-Za-z_][^;{}#]*?\b([A-Za-z_]\w*)[ \t]*[(\[]", re.M)
foreign = {}  # (header, c file) -> [symbols]
for h, t in text.items():
    if not h.endswith(".h"):
        continue
    own = h[:-len("_private.h")] + ".c" if h.endswith("_private.h") else None
    for name in declares.findall(t):
        if name in defined and defined[name] != own:
            foreign.setdefault((h, defined[name]), []).append(name)
def reached(f):
    seen, todo = [], list(includes[f])
    while todo:
        h = todo.pop(0)
        if h not in seen:
            seen.append(h)
            todo.extend(includes[h])
    return seen
include_edges, include_why = {}, {}
for f in sorted(t for t in text if t.endswith(".c")):
    targets = set()
    for h in reached(f):
        for c, names in stands_for[h].items():
            if c != f:
                targets.add(c)
                include_why.setdefault((f, c), []).append(f"{h}: {' '.join(names[:3])}{' ...' if len(names) > 3 else ''}")
    include_edges[f] = sorted(targets)

def strongly_connected(edges):
    """Tarjan's strongly connected components of two or more nodes."""
    index, low, stack, on, comps, counter = {}, {}, [], set(), [], [0]
    def visit(v):
        index[v] = low[v] = counter[0]
        counter[0] += 1
        stack.append(v)
        on.add(v)
        for w in edges.get(v, ()):
            if w not in index:
                visit(w)
                low[v] = min(low[v], low[w])
            elif w in on:
                low[v] = min(low[v], index[w])
        if low[v] == index[v]:
            comp = []
            while True:
                w = stack.pop()
                on.discard(w)
                comp.append(w)
                if w == v:
                    break
            if len(comp) > 1:
                comps.append(sorted(comp))
    for v in sorted(edges):
        if v not in index:
            visit(v)
    return sorted(comps)
sys.setrecursionlimit(10000)
comps = strongly_connected(edges)
include_comps = strongly_connected(include_edges)

findings = []  # (key, line)
for comp in comps:
    detail = "; ".join(f"{a} -> {b}" for a in comp for b in edges[a] if b in comp)
    findings.append((("circle",) + tuple(comp), "circle " + " ".join(comp) + f"   ({detail})"))
for comp in include_comps:
    detail = "".join(f"\n        {a} -> {b} by {', '.join(include_why[(a, b)])}"
                     for a in comp for b in include_edges[a] if b in comp)
    findings.append((("include-circle",) + tuple(comp), "include-circle " + " ".join(comp) + detail))
for (h, c), names in sorted(foreign.items()):
    findings.append((("declares", h, c), f"declares {h} {c} {' '.join(sorted(set(names)))}"))
for line in open(findings_file):
    kind, f, fn, value = line.split()
    findings.append(((kind, f, fn), line.strip()))

known = set()
if known_file:
    for line in open(known_file):
        line = line.split("#", 1)[0].split()
        if line:
            known.add(tuple(line) if not line[0].endswith("circle") else (line[0],) + tuple(sorted(line[1:])))
new = 0
for key, text in findings:
    if key in known:
        print("known:", text)
    else:
        print("NEW:  ", text)
        new += 1
found = {key for key, _ in findings}
for key in sorted(known - found):
    print("gone (remove it from the known list):", " ".join(key))
print(f"check_shape: {len(files)} object files, {len(comps)} circles by symbols, "
      f"{len(include_comps)} by includes ({len(stands_for)} headers), "
      f"{sum(1 for k, _ in findings if k[0] == 'long')} functions over 80 lines, "
      f"{sum(1 for k, _ in findings if k[0] == 'complex')} over complexity 20; {new} new")
sys.exit(1 if new else 0)
PY
