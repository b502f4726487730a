#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Instructions per function from a QEMU `-d in_asm,exec,nochain` trace.

usage: qemu_profile.py ELF START STOP [TRACE]   (TRACE defaults to stdin)

Counts the guest instructions executed from the second entry into function
START (the first is the warm-up frame of ports/mps2/main_torus.c) to the
next entry into STOP, per function (addresses from arm-none-eabi-nm).  A
library helper (a name starting with "__") is charged to the function that
called it, with the number of calls, so "shade_unit __aeabi_ldivmod" is the
64-bit division shade_unit pays for.  Each translated block's size is taken
from its latest `IN:` listing; with -icount the totals match the SysTick
count to within a few hundred instructions.
"""
import bisect
import collections
import re
import subprocess
import sys


def symbols(elf):
    out = subprocess.run(['arm-none-eabi-nm', '-n', elf], capture_output=True, text=True,
                         check=True).stdout
    syms = []
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[1] in 'tTwW':
            syms.append((int(parts[0], 16) & ~1, parts[2]))
    syms.sort()
    return syms


def main():
    if len(sys.argv) not in (4, 5):
        sys.exit(__doc__)
    elf, start, stop = sys.argv[1:4]
    trace = open(sys.argv[4]) if len(sys.argv) == 5 else sys.stdin
    syms = symbols(elf)
    addrs = [a for a, _ in syms]
    where = {name: a for a, name in syms}
    for name in (start, stop):
        if name not in where:
            sys.exit('%s: no function %s in %s' % (sys.argv[0], name, elf))

    def function_at(pc):
        i = bisect.bisect_right(addrs, pc) - 1
        return syms[i][1] if i >= 0 else '?'

    in_re = re.compile(r'^0x([0-9a-f]+):')
    exec_re = re.compile(r'^Trace \d+: \S+ \[[0-9a-f]+/([0-9a-f]+)/')
    size, block = {}, None
    count, calls = collections.Counter(), collections.Counter()
    entries, counting, caller, helper = 0, False, '?', None
    for line in trace:
        if line.startswith('IN:'):
            block = None
            continue
        m = in_re.match(line)
        if m:
            pc = int(m.group(1), 16)
            if block is None:
                block, size[pc] = pc, 0
            size[block] += 1
            continue
        m = exec_re.match(line)
        if not m:
            continue
        block = None
        pc = int(m.group(1), 16)
        if pc == where[start]:
            entries += 1
            counting = counting or entries == 2
        if counting and pc == where[stop]:
            break
        if not counting:
            continue
        name = function_at(pc)
        if name.startswith('__'):
            if helper is None:
                helper = name
                calls[(caller, name)] += 1
            count[(caller, helper)] += size.get(pc, 0)
        else:
            helper, caller = None, name
            count[(name, '')] += size.get(pc, 0)
    if not counting:
        sys.exit('%s: %s was not entered twice' % (sys.argv[0], start))
    total = sum(count.values())
    print('%d instructions from the second entry into %s to %s' % (total, start, stop))
    for (name, lib), n in count.most_common(40):
        extra = ' %-16s %6d calls' % (lib, calls[(name, lib)]) if lib else ''
        print('%9d %5.1f%%  %s%s' % (n, 100.0 * n / total, name, extra))


if __name__ == '__main__':
    main()
