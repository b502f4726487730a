#!/bin/sh
# SPDX-License-Identifier: MIT
# The shape of the core (src/): no import circle between its object files,
# no function over 80 lines or of cyclomatic complexity over 20.
#
#   scripts/check_shape.sh [--known FILE] [--cc CC] [ROOT]
#
# Import circles are found by the symbols the object files use, not by their
# #includes: each src/*.c is compiled (CC, default cc; -O1, the default
# configuration) and nm lists what it defines and what it needs; a file
# using a symbol another defines depends on it, and every strongly connected
# group of two or more files is a circle.  Function sizes come from pmccabe
# (Debian package pmccabe): its traditional McCabe complexity and its line
# count of each function.
#
# Every finding is printed as one line:
#   circle a.c b.c ...        (the files of the circle, sorted)
#   long FILE FUNCTION LINES
#   complex FILE FUNCTION COMPLEXITY
# With --known FILE (lines "circle a.c b.c", "long FILE FUNCTION",
# "complex FILE FUNCTION"; # comments), the known offenders are reported
# but pass, and the script fails only on new ones; a known offender that is
# gone is reported so the list can shrink.  Exit status 0: no new offender;
# 1: a new one; 2: usage or a missing tool.
set -eu
known=
cc=${CC:-cc}
while [ $# -gt 0 ]; do
    case $1 in
    --known) known=$2; shift 2 ;;
    --cc) cc=$2; shift 2 ;;
    -h | --help) sed -n '3,24p' "$0"; exit 0 ;;
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

# 1. symbols defined and used by each object file
for src in "$root"/src/*.c; do
    name=$(basename "$src")
    "$cc" -std=c99 -O1 -I "$root/include" -I "$root/src" -c "$src" -o "$work/$name.o" ||
        { echo "check_shape: $src does not compile" >&2; exit 2; }
    nm --defined-only -g "$work/$name.o" | awk -v f="$name" 'NF >= 3 { print "D", f, $3 }' >>"$work/symbols"
    nm -u "$work/$name.o" | awk -v f="$name" '{ print "U", f, $NF }' >>"$work/symbols"
done

# 2. function sizes
pmccabe "$root"/src/*.c 2>/dev/null | awk '{
    split($6, where, "("); file = where[1]; sub(".*/", "", file)
    if ($5 > 80) print "long", file, $7, $5
    if ($2 > 20) print "complex", file, $7, $2
}' >"$work/findings"

# 3. circles, and the comparison with the known list
python3 - "$work/symbols" "$work/findings" "$known" <<'PY'
import sys

symbols, findings_file, known_file = sys.argv[1], sys.argv[2], sys.argv[3]
defined, uses = {}, {}
for line in open(symbols):
    kind, f, sym = line.split()
    if kind == "D":
        defined[sym] = f
    else:
        uses.setdefault(f, set()).add(sym)
files = sorted(set(defined.values()) | set(uses))
edges = {f: sorted({defined[s] for s in uses.get(f, ()) if s in defined and defined[s] != f}) for f in files}

# Tarjan's strongly connected components
index, low, stack, on, comps, counter = {}, {}, [], set(), [], [0]
def visit(v):
    index[v] = low[v] = counter[0]
    counter[0] += 1
    stack.append(v)
    on.add(v)
    for w in edges[v]:
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
sys.setrecursionlimit(10000)
for f in files:
    if f not in index:
        visit(f)

findings = []  # (key, line)
for comp in sorted(comps):
    detail = "; ".join(f"{a} -> {b}" for a in comp for b in edges[a] if b in comp)
    findings.append((("circle",) + tuple(comp), "circle " + " ".join(comp) + f"   ({detail})"))
for line in open(findings_file):
    kind, f, fn, value = line.split()
    findings.append(((kind, f, fn), line.strip()))

known = set()
if known_file:
    for line in open(known_file):
        line = line.split("#", 1)[0].split()
        if line:
            known.add(tuple(line) if line[0] != "circle" else ("circle",) + tuple(sorted(line[1:])))
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
print(f"check_shape: {len(files)} object files, {len(comps)} circles, "
      f"{sum(1 for k, _ in findings if k[0] == 'long')} functions over 80 lines, "
      f"{sum(1 for k, _ in findings if k[0] == 'complex')} over complexity 20; {new} new")
sys.exit(1 if new else 0)
PY
