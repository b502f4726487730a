#!/usr/bin/env python3
# SPDX-License-Identifier: MIT
"""Cortex-M0+ cycle estimate from an instruction trace.

Reads QEMU's one-instruction-per-block execution trace (qemu-system-arm
-singlestep -d exec,nochain: one "Trace ..: HOST [../PC/../..] symbol"
line per executed instruction) on standard input, classifies every
executed instruction by the firmware's disassembly (arm-none-eabi-objdump
-d of ELF), and prints the instructions and the estimated cycles inside
the measured window: from the third-last call of the firmware's
stp_count_now to its last call (t0 .. t2 of ports/mps2/main_torus.c and
main_direct.c).

Cycle model: the Cortex-M0+ Technical Reference Manual's instruction
timings on zero-wait-state memory, with the single-cycle multiplier:
  1    every instruction not listed below (MULS included)
  2    LDR*, STR* (one register); B, B<cond> taken; BX, BLX; MOV/ADD to PC
  3    BL; DMB, DSB, ISB; MRS, MSR
  1+N  LDM, STM, PUSH, POP of N registers (POP with PC: 3+N)
  1    B<cond> not taken
Exception entry adds 15 cycles where the trace leaves an instruction that
does not write the PC (the latency the TRM gives), so a timer interrupt in
the window is counted as the core would spend it.
"""
import argparse
import re
import subprocess
import sys

LINE = re.compile(r"^\s*([0-9a-f]+):\s+((?:[0-9a-f]{4}\s?)+)\s+(\S+)\s*(.*)$")


def register_count(operands):
    """Registers in a {list}, ranges like r4-r7 included."""
    inside = operands[operands.find("{") + 1:operands.find("}")]
    n = 0
    for part in inside.split(","):
        part = part.strip()
        if "-" in part:
            lo, hi = part.split("-")
            n += int(hi.strip()[1:]) - int(lo.strip()[1:]) + 1
        elif part:
            n += 1
    return n


def classify(mnemonic, operands):
    """(cycles if it falls through, cycles if it changes the PC, writes PC)"""
    m = mnemonic.split(".")[0]
    ops = operands.split(";")[0].strip()
    if m in ("push", "stmia", "stm", "ldmia", "ldm"):
        n = register_count(ops)
        return 1 + n, 1 + n, False
    if m == "pop":
        n = register_count(ops)
        if "pc" in ops.split("}")[0]:
            return 3 + n, 3 + n, True
        return 1 + n, 1 + n, False
    if m.startswith("ldr") or m.startswith("str"):
        return 2, 2, False
    if m == "bl":
        return 3, 3, True
    if m in ("bx", "blx"):
        return 2, 2, True
    if m == "b":
        return 2, 2, True
    if re.fullmatch(r"b(eq|ne|cs|hs|cc|lo|mi|pl|vs|vc|hi|ls|ge|lt|gt|le)", m):
        return 1, 2, True
    if m in ("dmb", "dsb", "isb", "mrs", "msr"):
        return 3, 3, False
    if m in ("mov", "add") and ops.startswith("pc"):
        return 2, 2, True
    return 1, 1, False


def disassemble(elf, objdump):
    table = {}
    out = subprocess.run([objdump, "-d", elf], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        g = LINE.match(line)
        if not g:
            continue
        addr = int(g.group(1), 16)
        size = 2 * len(g.group(2).split())
        through, taken, writes_pc = classify(g.group(3), g.group(4))
        table[addr] = (size, through, taken, writes_pc)
    return table


def symbol_address(elf, name, nm):
    out = subprocess.run([nm, elf], check=True, capture_output=True, text=True).stdout
    for line in out.splitlines():
        parts = line.split()
        if len(parts) == 3 and parts[2] == name:
            return int(parts[0], 16) & ~1
    sys.exit(f"m0_cycles: {elf} has no symbol {name}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("elf")
    ap.add_argument("--mark", default="stp_count_now",
                    help="the function whose last three calls bound the window")
    ap.add_argument("--clock", type=float, default=48e6, help="Hz, for frames per second")
    ap.add_argument("--objdump", default="arm-none-eabi-objdump")
    ap.add_argument("--nm", default="arm-none-eabi-nm")
    ap.add_argument("--profile", type=int, default=0, metavar="N",
                    help="print the N functions with the most cycles in the window")
    a = ap.parse_args()
    table = disassemble(a.elf, a.objdump)
    mark = symbol_address(a.elf, a.mark, a.nm)
    # per segment between entries of the mark: [instructions, cycles, taken, exceptions]
    segments = []
    profiles = []  # per segment: symbol -> [instructions, cycles]
    cur = [0, 0, 0, 0]
    prof = {}
    prev_symbol = "?"
    prev = None
    unknown = 0
    for line in sys.stdin:
        if not line.startswith("Trace"):
            continue
        b = line.find("[")
        pc = int(line[b + 10:b + 18], 16)
        cycles_before = cur[1]
        if prev is not None:
            info = table.get(prev)
            if info is None:
                unknown += 1
                cur[0] += 1
                cur[1] += 1
            else:
                size, through, taken, writes_pc = info
                cur[0] += 1
                if pc == prev + size:
                    cur[1] += through
                elif writes_pc:
                    cur[1] += taken
                    cur[2] += 1
                else:
                    cur[1] += through + 15  # exception entry
                    cur[3] += 1
        if a.profile and prev is not None:
            entry = prof.setdefault(prev_symbol, [0, 0])
            entry[0] += 1
            entry[1] += cur[1] - cycles_before
        if pc == mark:
            segments.append(cur)
            profiles.append(prof)
            cur = [0, 0, 0, 0]
            prof = {}
        prev = pc
        if a.profile:
            tail = line[line.find("]", b) + 1:].split()
            prev_symbol = tail[0] if tail else "?"
    if len(segments) < 3:
        sys.exit(f"m0_cycles: {a.mark} entered {len(segments)} times, need 3 (t0, t1, t2)")
    window = [x + y for x, y in zip(segments[-2], segments[-1])]
    instructions, cycles = window[0], window[1]
    print(f"m0_cycles: instructions in the window {instructions}")
    print(f"m0_cycles: estimated Cortex-M0+ cycles {cycles} "
          f"({cycles / instructions:.3f} a instruction; taken branches {window[2]}, "
          f"exception entries {window[3]})")
    print(f"m0_cycles: {a.clock / cycles:.1f} frames/s at {a.clock / 1e6:g} MHz")
    if a.profile:
        merged = {}
        for part in profiles[-2:]:
            for name, (n, c) in part.items():
                m = merged.setdefault(name, [0, 0])
                m[0] += n
                m[1] += c
        print(f"m0_cycles: profile of the window, self cost ({len(merged)} functions)")
        print(f"{'cycles':>10} {'instructions':>13}  function")
        for name, (n, c) in sorted(merged.items(), key=lambda kv: -kv[1][1])[:a.profile]:
            print(f"{c:>10} {n:>13}  {name}")
    if unknown:
        print(f"m0_cycles: {unknown} executed addresses not in the disassembly, counted as 1 cycle")


if __name__ == "__main__":
    main()
