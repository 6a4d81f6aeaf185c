#!/usr/bin/env python3
"""Size of a SPIR-V module once every function call is inlined, as a driver that inlines
everything (lavapipe's NIR does) sees it, and the functions that contribute most.

Usage: spirv-dis MODULE.spv | bench/spirv_inlined_size.py [--top N]

A function's inlined size is its own instruction count plus the inlined sizes of its callees,
once per call; its contribution to the entry point is (times inlined) x (own instructions).
"""
import argparse
import collections
import re
import sys


def parse(lines):
    names, funcs, current = {}, {}, None
    for line in lines:
        m = re.match(r'\s*OpName (%\S+) "([^"]*)"', line)
        if m:
            names[m.group(1)] = m.group(2)
        m = re.match(r"\s*(%\S+) = OpFunction ", line)
        if m:
            current = m.group(1)
            funcs[current] = {"own": 0, "calls": []}
            continue
        if current is None:
            continue
        if "OpFunctionEnd" in line:
            current = None
            continue
        funcs[current]["own"] += 1
        m = re.search(r"OpFunctionCall %\S+ (%\S+)", line)
        if m:
            funcs[current]["calls"].append(m.group(1))
    return names, funcs


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("--top", type=int, default=20)
    args = ap.parse_args()
    names, funcs = parse(sys.stdin)
    entry = next(f for f in funcs if names.get(f) == "main")
    order, seen = [], set()

    def visit(f):
        if f in seen:
            return
        seen.add(f)
        for c in funcs[f]["calls"]:
            visit(c)
        order.append(f)

    visit(entry)
    times = collections.defaultdict(int)
    times[entry] = 1
    for f in reversed(order):
        for c in funcs[f]["calls"]:
            times[c] += times[f]
    total = sum(times[f] * funcs[f]["own"] for f in order)
    print(f"inlined instructions: {total} (own instructions of all functions: "
          f"{sum(funcs[f]['own'] for f in order)})")
    rows = sorted(((times[f] * funcs[f]["own"], times[f], funcs[f]["own"], names.get(f, f))
                   for f in order), reverse=True)
    print(f"{'inlined':>9} {'times':>6} {'own':>5}  function")
    for contribution, t, own, name in rows[: args.top]:
        print(f"{contribution:>9} {t:>6} {own:>5}  {name.split('(')[0]}")


if __name__ == "__main__":
    main()
