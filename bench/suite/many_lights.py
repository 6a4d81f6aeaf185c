#!/usr/bin/env python3
"""Issue 15's many-light benchmark: the emitter selections of `twinray render
--emitter-selection` (uniform: Mitsuba's; power; bvh: the light BVH) on gen.py's emitter scenes
(N small emissive triangles of log-uniform power above a diffuse plane).

usage: bench/suite/many_lights.py [--full] [--write] OUT_DIR
  OUT_DIR  generated scenes, renders and logs (never inside the repository)
  --full   also N = 1e5 (loads 1e5 PLY files: about 0.5 GiB), and 8 seeds instead of 4
  --write  replace the table between the bench/many_lights markers of BENCHMARKS.md and write
           bench/plots/many_lights.svg
env: TWINRAY (build/app/twinray), THREADS (2)

Three measurements, all at 128x128, max_depth 4, on the CPU backend:
- cost: the render phase's marginal time per sample (twinray's own summary, whose time counts the
  Embree build and the sampling, not scene loading): the difference between renders of 80 and 16
  spp over their 64 spp of difference (median of three), for each N and selection;
- the same cost with the geometry held fixed (gen.py emitters --triangles T: T triangles, the
  first N emissive, T = 1e4, or 1e5 with --full), so that it measures what N emitters cost and
  not what T shapes cost to trace and shade;
- error at equal time: for N = 1e3 and 1e4 (and 1e5 with --full), each selection renders for the
  same time (--time 4) with several seeds; relMSE against a reference (the light BVH at 4096
  spp) as `twinray compare` computes it; mean and standard error over the seeds.
"""
import math
import os
import re
import subprocess
import sys
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
TWINRAY = os.environ.get("TWINRAY", os.path.join(ROOT, "build", "app", "twinray"))
THREADS = os.environ.get("THREADS", "2")
SELECTIONS = ["uniform", "power", "bvh"]
RES = ["-D", "width=128", "-D", "height=128"]
EQUAL_TIME_S = 4.0
REFERENCE_SPP = 4096
COST_REPEATS = 3
SUMMARY = re.compile(r"^twinray: \d+x\d+, (\d+) spp, ([0-9.]+) s, ([0-9.]+) Msamples/s", re.M)


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"many_lights: {' '.join(cmd)} failed ({r.returncode}):\n{r.stderr}")
    return r.stdout + r.stderr


def render(scene, out, selection, extra):
    log = run([TWINRAY, "render", scene, "-o", out, "--threads", THREADS,
               "--emitter-selection", selection] + RES + extra)
    m = SUMMARY.search(log)
    if not m:
        sys.exit(f"many_lights: no summary line from {scene}:\n{log}")
    return int(m.group(1)), float(m.group(2))


def generate(out, args):
    return run([sys.executable, os.path.join(HERE, "gen.py"), "emitters", out] + args).strip()


def marginal_cost(scene, out, label, n, selection):
    """µs per sample: the render phase includes the Embree build, which grows with the shapes,
    so the marginal cost of a sample is the difference of two renders over their samples'
    difference; the median of COST_REPEATS such differences (one alone varies by about ±0.1 µs
    on the shared 2-core machines)."""
    exr = os.path.join(out, f"{label}_{n}_{selection}.exr")
    runs = []
    for _ in range(COST_REPEATS):
        spp0, t0 = render(scene, exr, selection, ["-D", "spp=16"])
        spp1, t1 = render(scene, exr, selection, ["-D", "spp=80"])
        runs.append((t1 - t0) / (128 * 128 * (spp1 - spp0)) * 1e6)
    us = sorted(runs)[COST_REPEATS // 2]
    print(f"{label} N={n} {selection}: {us:.3f} µs/sample", file=sys.stderr)
    return us


def rel_mse(test, reference):
    out = run([TWINRAY, "compare", test, reference])
    m = re.search(r"relMSE ([0-9.eE+-]+)", out)
    if not m:
        sys.exit(f"many_lights: no relMSE in compare output:\n{out}")
    return float(m.group(1))


def mean_and_error(xs):
    m = sum(xs) / len(xs)
    if len(xs) < 2:
        return m, 0.0
    var = sum((x - m) ** 2 for x in xs) / (len(xs) - 1)
    return m, math.sqrt(var / len(xs))


def svg_plot(cost, error, counts, error_counts):
    """Two log-log panels: time per sample against N, relMSE at equal time against N."""
    w, h, pad = 420, 300, 55
    colours = {"uniform": "#d62728", "power": "#1f77b4", "bvh": "#2ca02c"}

    def panel(x0, title, ylabel, series, xs, yerr=None):
        ys = [y for s in series.values() for y in s if y > 0]
        lx0, lx1 = math.log10(min(xs)), math.log10(max(xs))
        ly0, ly1 = math.floor(math.log10(min(ys))), math.ceil(math.log10(max(ys)))
        if ly1 == ly0:
            ly1 += 1
        lx1 = lx1 if lx1 > lx0 else lx0 + 1

        def px(x):
            return x0 + pad + (math.log10(x) - lx0) / (lx1 - lx0) * (w - 1.5 * pad)

        def py_(y):
            return (h - pad) - (math.log10(y) - ly0) / (ly1 - ly0) * (h - 1.7 * pad)

        parts = [f'<text x="{x0 + w / 2}" y="18" text-anchor="middle" font-size="13">{title}</text>',
                 f'<rect x="{x0 + pad}" y="{0.7 * pad}" width="{w - 1.5 * pad}" '
                 f'height="{h - 1.7 * pad}" fill="none" stroke="#888"/>']
        for e in range(int(lx0), int(math.ceil(lx1)) + 1):
            x = px(10 ** e)
            parts.append(f'<text x="{x}" y="{h - pad + 16}" text-anchor="middle" '
                         f'font-size="11">1e{e}</text>')
        for e in range(ly0, ly1 + 1):
            y = py_(10 ** e)
            parts.append(f'<text x="{x0 + pad - 4}" y="{y + 4}" text-anchor="end" '
                         f'font-size="11">1e{e}</text>')
            parts.append(f'<line x1="{x0 + pad}" x2="{x0 + w - 0.5 * pad}" y1="{y}" y2="{y}" '
                         f'stroke="#eee"/>')
        parts.append(f'<text x="{x0 + w / 2}" y="{h - 12}" text-anchor="middle" '
                     f'font-size="12">emitters</text>')
        parts.append(f'<text x="{x0 + 14}" y="{h / 2}" text-anchor="middle" font-size="12" '
                     f'transform="rotate(-90 {x0 + 14} {h / 2})">{ylabel}</text>')
        for i, (name, s) in enumerate(series.items()):
            pts = [(px(x), py_(y)) for x, y in zip(xs, s) if y > 0]
            c = colours[name]
            parts.append('<polyline fill="none" stroke="{}" stroke-width="2" points="{}"/>'.format(
                c, " ".join(f"{a:.1f},{b:.1f}" for a, b in pts)))
            for (a, b), k in zip(pts, range(len(pts))):
                parts.append(f'<circle cx="{a:.1f}" cy="{b:.1f}" r="3" fill="{c}"/>')
                if yerr:
                    e = yerr[name][k]
                    y = s[k]
                    if e > 0 and y - e > 0:
                        parts.append(f'<line x1="{a:.1f}" x2="{a:.1f}" y1="{py_(y - e):.1f}" '
                                     f'y2="{py_(y + e):.1f}" stroke="{c}"/>')
            parts.append(f'<text x="{x0 + pad + 8}" y="{0.7 * pad + 16 + 14 * i}" fill="{c}" '
                         f'font-size="12">{name}</text>')
        return parts

    body = panel(0, "render time per sample", "µs per sample",
                 {s: [cost[(n, s)] for n in counts] for s in SELECTIONS}, counts)
    body += panel(w, f"relMSE after {EQUAL_TIME_S:g} s of rendering", "relMSE",
                  {s: [error[(n, s)][0] for n in error_counts] for s in SELECTIONS}, error_counts,
                  {s: [error[(n, s)][1] for n in error_counts] for s in SELECTIONS})
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{2 * w}" height="{h}" '
            f'font-family="sans-serif">\n<rect width="100%" height="100%" fill="white"/>\n' +
            "\n".join(body) + "\n</svg>\n")


def main():
    args = sys.argv[1:]
    full, write = "--full" in args, "--write" in args
    rest = [a for a in args if not a.startswith("--")]
    if len(rest) != 1 or any(a not in ("--full", "--write") for a in args if a.startswith("--")):
        sys.exit(__doc__)
    out = os.path.abspath(rest[0])
    if out.startswith(ROOT + os.sep):
        sys.exit(f"many_lights: OUT_DIR must be outside the repository ({ROOT})")
    os.makedirs(out, exist_ok=True)
    counts = [1, 10, 100, 1000, 10000] + ([100000] if full else [])
    error_counts = [1000, 10000] + ([100000] if full else [])
    seeds = range(8 if full else 4)
    uptime_before = run(["uptime"]).strip()

    scenes, fixed_scenes = {}, {}
    triangles = max(counts)
    for n in counts:
        scenes[n] = generate(out, ["--count", str(n)])
        fixed_scenes[n] = generate(out, ["--count", str(n), "--triangles", str(triangles)])

    cost = {n_s: marginal_cost(scenes[n_s[0]], out, "cost", *n_s)
            for n_s in ((n, s) for n in counts for s in SELECTIONS)}
    fixed_cost = {n_s: marginal_cost(fixed_scenes[n_s[0]], out, "fixed_cost", *n_s)
                  for n_s in ((n, s) for n in counts for s in SELECTIONS)}

    error = {}
    for n in error_counts:
        reference = os.path.join(out, f"reference_{n}.exr")
        render(scenes[n], reference, "bvh", ["-D", f"spp={REFERENCE_SPP}", "--seed", "1000"])
        for s in SELECTIONS:
            values = []
            for seed in seeds:
                test = os.path.join(out, f"equal_time_{n}_{s}_{seed}.exr")
                render(scenes[n], test, s, ["-D", "spp=1000000", "--time", str(EQUAL_TIME_S),
                                            "--seed", str(seed)])
                values.append(rel_mse(test, reference))
            error[(n, s)] = mean_and_error(values)
            print(f"N={n} {s}: relMSE {error[(n, s)][0]:.4g} ± {error[(n, s)][1]:.2g}",
                  file=sys.stderr)

    lines = ["| emitters | " + " | ".join(f"{s} µs/sample" for s in SELECTIONS) +
             " | bvh cost ÷ its cost at 1 emitter | " +
             " | ".join(f"{s} relMSE at {EQUAL_TIME_S:g} s" for s in SELECTIONS) +
             " | uniform ÷ bvh relMSE |",
             "|---" * (2 * len(SELECTIONS) + 3) + "|"]
    for n in counts:
        row = [f"{n}"] + [f"{cost[(n, s)]:.3f}" for s in SELECTIONS]
        row.append(f"{cost[(n, 'bvh')] / cost[(1, 'bvh')]:.2f}")
        if n in error_counts:
            row += [f"{error[(n, s)][0]:.4g} ± {error[(n, s)][1]:.2g}" for s in SELECTIONS]
            row.append(f"{error[(n, 'uniform')][0] / error[(n, 'bvh')][0]:.1f}")
        else:
            row += ["–"] * (len(SELECTIONS) + 1)
        lines.append("| " + " | ".join(row) + " |")
    lines += ["", f"The same cost with the geometry held fixed: {triangles} triangles, the "
              f"first N of them emissive.", "",
              "| emitters | " + " | ".join(f"{s} µs/sample" for s in SELECTIONS) +
              " | bvh cost ÷ its cost at 1 emitter |",
              "|---" * (len(SELECTIONS) + 2) + "|"]
    for n in counts:
        row = [f"{n} of {triangles}"] + [f"{fixed_cost[(n, s)]:.3f}" for s in SELECTIONS]
        row.append(f"{fixed_cost[(n, 'bvh')] / fixed_cost[(1, 'bvh')]:.2f}")
        lines.append("| " + " | ".join(row) + " |")
    table = "\n".join(lines)
    print(table)

    if write:
        plot = os.path.join(ROOT, "bench", "plots", "many_lights.svg")
        os.makedirs(os.path.dirname(plot), exist_ok=True)
        with open(plot, "w") as f:
            f.write(svg_plot(cost, error, counts, error_counts))
        describe = run(["git", "-C", ROOT, "describe", "--always", "--dirty"]).strip()
        block = "\n".join([
            "<!-- bench/many_lights begin -->",
            f"Measured {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} by "
            f"`bench/suite/many_lights.py {'--full ' if full else ''}--write OUT_DIR` (the "
            f"checkout at {describe}, {THREADS} threads, {os.cpu_count()} cores; `uptime` before: "
            f"`{uptime_before}`, after: `{run(['uptime']).strip()}`); {len(seeds)} seeds for the "
            f"error, reference: bvh at {REFERENCE_SPP} spp.",
            "",
            table,
            "",
            "![many lights](bench/plots/many_lights.svg)",
            "<!-- bench/many_lights end -->"])
        bm = os.path.join(ROOT, "BENCHMARKS.md")
        text = open(bm).read()
        begin, end = "<!-- bench/many_lights begin -->", "<!-- bench/many_lights end -->"
        if begin not in text or end not in text:
            sys.exit(f"many_lights: {bm} has no bench/many_lights markers")
        a, b = text.index(begin), text.index(end) + len(end)
        with open(bm, "w") as f:
            f.write(text[:a] + block + text[b:])
        print(f"many_lights: wrote the table into {bm} and {plot}", file=sys.stderr)


if __name__ == "__main__":
    main()
