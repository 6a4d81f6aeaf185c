#!/usr/bin/env python3
"""Issue 15's scaling benchmark: the CPU backend's render-phase time per sample against the
triangle count, the thread count, the resolution and max_depth.

usage: bench/suite/scaling.py [--full] [--smoke] [--write] OUT_DIR
  OUT_DIR  generated scenes, renders and logs (never inside the repository)
  --full   also 1e7 triangles (a 190 MB PLY: about 10 s to generate and 10 s to load, 3 times)
  --smoke  tiny sizes (16 to 32 pixels a side, 1 to 4 spp, up to 1e4 triangles, one run each)
           to check the script in seconds; its figures mean nothing and --write is refused
  --write  replace the table between the bench/scaling markers of BENCHMARKS.md and write
           bench/plots/scaling.svg
env: TWINRAY (build/app/twinray), THREADS (2: the thread count of every measurement but the
     thread sweep)

Four measurements on the CPU backend, each from twinray's summary line (the render phase: the
Embree BVH build and the sampling, not the scene load):
- triangles: gen.py's mesh scenes (a displaced sphere of N triangles in a lit box, max_depth
  6) for N = 1e3 .. 1e6, 128x128, 16 spp; also at 1 and 65 spp, so that the difference of
  those two render times, over the 64 extra samples a pixel, is the time per sample without
  the BVH build and the other once-per-render costs (the build's time varies by about 0.1 s
  from run to run at 1e6 triangles: 15 extra samples a pixel would not hide that);
- threads: twinray's default Cornell box (max_depth 8), 256x256, 32 spp, with --threads 1, 2
  (and powers of two up to the core count), the median of 3 runs each; Msamples/s and the
  speed-up over one thread;
- resolution: the Cornell box at 64, 128, 256 and 512 pixels square, 16 spp;
- max_depth: the Cornell box at max_depth 1, 2, 4, 8 and 16, 128x128, 32 spp.
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
CORNELL = os.path.join(ROOT, "examples", "scenes", "cornell-box", "cornell_box.xml")
SUMMARY = re.compile(r"^twinray: (\d+)x(\d+), (\d+) spp, ([0-9.]+) s, ([0-9.]+) Msamples/s", re.M)
BEGIN, END = "<!-- bench/scaling begin -->", "<!-- bench/scaling end -->"


def settings(full, smoke):
    if smoke:
        return {"triangles": [1000, 10000], "tri_side": 32, "tri_spp": 4, "tri_long_spp": 8,
                "threads": [1, 2], "thr_side": 32, "thr_spp": 1, "thr_runs": 1,
                "resolutions": [16, 32], "res_spp": 1,
                "depths": [1, 2, 4], "depth_side": 32, "depth_spp": 1}
    threads = [1, 2]
    while threads[-1] * 2 <= (os.cpu_count() or 1):
        threads.append(threads[-1] * 2)
    return {"triangles": [10 ** k for k in range(3, 8 if full else 7)], "tri_side": 128,
            "tri_spp": 16, "tri_long_spp": 65, "threads": threads, "thr_side": 256,
            "thr_spp": 32, "thr_runs": 3,
            "resolutions": [64, 128, 256, 512], "res_spp": 16,
            "depths": [1, 2, 4, 8, 16], "depth_side": 128, "depth_spp": 32}


def default_max_depth(scene):
    m = re.search(r'<default name="max_depth" value="(\d+)"/>', open(scene).read())
    if not m:
        sys.exit(f"scaling: {scene} has no <default name=\"max_depth\">")
    return int(m.group(1))


def run(cmd):
    r = subprocess.run(cmd, capture_output=True, text=True)
    if r.returncode != 0:
        sys.exit(f"scaling: {' '.join(cmd)} failed ({r.returncode}):\n{r.stderr}")
    return r.stdout + r.stderr


def render(scene, out, side, spp, threads=None, max_depth=None):
    """Renders side x side at spp; returns (samples, render-phase seconds)."""
    cmd = [TWINRAY, "render", scene, "-o", out, "--threads", str(threads or THREADS),
           "-D", f"width={side}", "-D", f"height={side}", "-D", f"spp={spp}"]
    if max_depth is not None:
        cmd += ["-D", f"max_depth={max_depth}"]
    log = run(cmd)
    m = SUMMARY.search(log)
    if not m:
        sys.exit(f"scaling: no summary line from {' '.join(cmd)}:\n{log}")
    w, h, got_spp, seconds = int(m.group(1)), int(m.group(2)), int(m.group(3)), float(m.group(4))
    if (w, h, got_spp) != (side, side, spp):
        sys.exit(f"scaling: asked {side}x{side}, {spp} spp of {scene}, twinray rendered "
                 f"{w}x{h}, {got_spp} spp")
    if seconds <= 0:
        sys.exit(f"scaling: {scene} at {side}x{side}, {spp} spp rendered in {seconds} s: too "
                 "short for twinray's millisecond figure")
    return w * h * got_spp, seconds


def log_ticks(lo, hi):
    """Round values inside [lo, hi]: 1, 2 and 5 times powers of ten, or finer steps where that
    gives fewer than three."""
    ticks = []
    for mantissas in ([1, 2, 5], [1, 1.2, 1.5, 2, 2.5, 3, 4, 5, 6, 7, 8, 9]):
        ticks = [m * 10.0 ** e for e in range(math.floor(math.log10(lo)),
                                             math.ceil(math.log10(hi)) + 1)
                 for m in mantissas if lo <= m * 10.0 ** e <= hi]
        if len(ticks) >= 3:
            break
    return ticks


def label(v):
    if v >= 1e3:
        e = math.floor(math.log10(v) + 1e-9)
        m = v / 10 ** e
        return f"1e{e}" if abs(m - 1) < 1e-6 else f"{m:.3g}e{e}"
    return f"{v:g}"


def panel(x0, y0, w, h, title, xlabel, ylabel, series, xticks):
    """A log-log panel at (x0, y0) of size w x h; series: [(name, colour, dashed, [(x, y)])]."""
    left, right, top, bottom = 58, 14, 26, 40
    xs = [x for _, _, _, pts in series for x, _ in pts]
    ys = [y for _, _, _, pts in series for _, y in pts]
    lx0, lx1 = math.log10(min(xs)), math.log10(max(xs))
    pad = 0.06 * (lx1 - lx0) if lx1 > lx0 else 0.5
    lx0, lx1 = lx0 - pad, lx1 + pad
    ly0, ly1 = math.log10(min(ys)), math.log10(max(ys))
    pad = 0.08 * (ly1 - ly0) if ly1 - ly0 > 0.3 else 0.15
    ly0, ly1 = ly0 - pad, ly1 + pad
    pw, ph = w - left - right, h - top - bottom

    def px(x):
        return x0 + left + (math.log10(x) - lx0) / (lx1 - lx0) * pw

    def py(y):
        return y0 + top + ph - (math.log10(y) - ly0) / (ly1 - ly0) * ph

    parts = [f'<text x="{x0 + left + pw / 2:.1f}" y="{y0 + 17}" text-anchor="middle" '
             f'font-size="13">{title}</text>']
    for t in log_ticks(10 ** ly0, 10 ** ly1):
        y = py(t)
        parts.append(f'<line x1="{x0 + left}" x2="{x0 + left + pw}" y1="{y:.1f}" y2="{y:.1f}" '
                     'stroke="#eee"/>')
        parts.append(f'<text x="{x0 + left - 4}" y="{y + 4:.1f}" text-anchor="end" '
                     f'font-size="11">{label(t)}</text>')
    for t in xticks:
        x = px(t)
        parts.append(f'<line x1="{x:.1f}" x2="{x:.1f}" y1="{y0 + top}" y2="{y0 + top + ph}" '
                     'stroke="#eee"/>')
        parts.append(f'<text x="{x:.1f}" y="{y0 + top + ph + 15}" text-anchor="middle" '
                     f'font-size="11">{label(t)}</text>')
    parts.append(f'<rect x="{x0 + left}" y="{y0 + top}" width="{pw}" height="{ph}" '
                 'fill="none" stroke="#888"/>')
    parts.append(f'<text x="{x0 + left + pw / 2:.1f}" y="{y0 + h - 6}" text-anchor="middle" '
                 f'font-size="12">{xlabel}</text>')
    cx, cy = x0 + 13, y0 + top + ph / 2
    parts.append(f'<text x="{cx}" y="{cy:.1f}" text-anchor="middle" font-size="12" '
                 f'transform="rotate(-90 {cx} {cy:.1f})">{ylabel}</text>')
    for i, (name, colour, dashed, pts) in enumerate(series):
        dash = ' stroke-dasharray="5,4"' if dashed else ""
        parts.append(f'<polyline fill="none" stroke="{colour}" stroke-width="2"{dash} points="' +
                     " ".join(f"{px(x):.1f},{py(y):.1f}" for x, y in pts) + '"/>')
        if not dashed:
            parts += [f'<circle cx="{px(x):.1f}" cy="{py(y):.1f}" r="3" fill="{colour}"/>'
                      for x, y in pts]
        if len(series) > 1:
            parts.append(f'<text x="{x0 + left + 6}" y="{y0 + top + 14 + 14 * i}" '
                         f'fill="{colour}" font-size="11">{name}</text>')
    return parts


def svg_plot(r):
    w, h = 400, 290
    blue, orange, grey = "#1f77b4", "#ff7f0e", "#888"
    tri = r["triangles"]
    decades = [10 ** e for e in range(math.floor(math.log10(min(t[0] for t in tri)) + 0.5),
                                      math.floor(math.log10(max(t[0] for t in tri)) + 0.5) + 1)]
    body = panel(0, 0, w, h, "time per sample against triangles", "triangles", "µs per sample",
                 [(f"render phase at {r['cfg']['tri_spp']} spp", blue, False,
                   [(t[0], t[4]) for t in tri]),
                  ("without the once-per-render costs", orange, False,
                   [(t[0], t[5]) for t in tri])], decades)
    thr = r["threads"]
    body += panel(w, 0, w, h, "throughput against threads", "threads", "Msamples/s",
                  [("measured (median of runs)", blue, False, [(t, ms) for t, ms, _ in thr]),
                   ("linear from one thread", grey, True, [(t, thr[0][1] * t) for t, _, _ in thr])],
                  [t for t, _, _ in thr])
    body += panel(0, h, w, h, "time per sample against resolution", "pixels a side",
                  "µs per sample", [("", blue, False, r["resolutions"])],
                  [s for s, _ in r["resolutions"]])
    body += panel(w, h, w, h, "time per sample against max_depth", "max_depth",
                  "µs per sample", [("", blue, False, r["depths"])], [d for d, _ in r["depths"]])
    return (f'<svg xmlns="http://www.w3.org/2000/svg" width="{2 * w}" height="{2 * h}" '
            'font-family="sans-serif">\n<rect width="100%" height="100%" fill="white"/>\n' +
            "\n".join(body) + "\n</svg>\n")


def tables(r):
    c = r["cfg"]
    lines = [f"Triangles (gen.py mesh, {c['tri_side']}×{c['tri_side']}, max_depth "
             f"{r['mesh_depth']}; \"without the once-per-render costs\" = (render s at "
             f"{c['tri_long_spp']} spp − at 1 spp) over the {c['tri_long_spp'] - 1} extra "
             "samples a pixel):", "",
             f"| triangles | render s at 1 spp | at {c['tri_spp']} spp | at {c['tri_long_spp']} "
             f"spp | µs/sample at {c['tri_spp']} spp (render phase) | µs/sample without the "
             "once-per-render costs |",
             "|---|---|---|---|---|---|"]
    lines += [f"| {n} | {t1:.3f} | {tn:.3f} | {tl:.3f} | {us:.3f} | {marginal:.3f} |"
              for n, t1, tn, tl, us, marginal in r["triangles"]]
    runs = c["thr_runs"]
    lines += ["", f"Threads (Cornell box, {c['thr_side']}×{c['thr_side']}, {c['thr_spp']} spp, "
              f"max_depth {r['cornell_depth']}; median of {runs} run{'s' if runs > 1 else ''}):",
              "",
              "| threads | Msamples/s | µs/sample | speed-up over 1 thread |", "|---|---|---|---|"]
    one = r["threads"][0][1]
    lines += [f"| {t} | {ms:.3f} | {1 / ms:.3f} | {ms / one:.2f} |" for t, ms, _ in r["threads"]]
    lines += ["", f"Resolution (Cornell box, {c['res_spp']} spp, max_depth "
              f"{r['cornell_depth']}):", "",
              "| pixels a side | µs/sample |", "|---|---|"]
    lines += [f"| {side} | {us:.3f} |" for side, us in r["resolutions"]]
    lines += ["", f"max_depth (Cornell box, {c['depth_side']}×{c['depth_side']}, "
              f"{c['depth_spp']} spp):", "", "| max_depth | µs/sample |", "|---|---|"]
    lines += [f"| {d} | {us:.3f} |" for d, us in r["depths"]]
    return "\n".join(lines)


def check_markers(bm):
    text = open(bm).read()
    if text.count(BEGIN) != 1 or text.count(END) != 1 or text.index(BEGIN) > text.index(END):
        sys.exit(f"scaling: {bm} needs one {BEGIN} followed by one {END}")
    return text


def write_results(bm, plot, r, table, header):
    text = check_markers(bm)
    os.makedirs(os.path.dirname(plot), exist_ok=True)
    with open(plot, "w") as f:
        f.write(svg_plot(r))
    link = os.path.relpath(plot, os.path.dirname(bm))
    block = "\n".join([BEGIN, header, "", table, "", f"![scaling]({link})", END])
    a, b = text.index(BEGIN), text.index(END) + len(END)
    with open(bm, "w") as f:
        f.write(text[:a] + block + text[b:])


def median(xs):
    s = sorted(xs)
    n = len(s)
    return s[n // 2] if n % 2 else 0.5 * (s[n // 2 - 1] + s[n // 2])


def main():
    args = sys.argv[1:]
    flags = {a for a in args if a.startswith("--")}
    rest = [a for a in args if not a.startswith("--")]
    if len(rest) != 1 or flags - {"--full", "--smoke", "--write"}:
        sys.exit(__doc__)
    full, smoke, write = "--full" in flags, "--smoke" in flags, "--write" in flags
    if smoke and (write or full):
        sys.exit("scaling: --smoke's figures are not measurements: it takes neither --write "
                 "nor --full")
    out = os.path.abspath(rest[0])
    if out == ROOT or out.startswith(ROOT + os.sep):
        sys.exit(f"scaling: OUT_DIR must be outside the repository ({ROOT})")
    if not os.path.isfile(TWINRAY):
        sys.exit(f"scaling: no twinray at {TWINRAY} (build it or set TWINRAY)")
    bm = os.path.join(ROOT, "BENCHMARKS.md")
    if write:
        check_markers(bm)
    os.makedirs(out, exist_ok=True)
    cfg = settings(full, smoke)
    start = time.time()
    uptime_before = run(["uptime"]).strip()
    r = {"cfg": cfg, "triangles": [], "threads": [], "resolutions": [], "depths": [],
         "cornell_depth": default_max_depth(CORNELL)}

    side, spp, long_spp = cfg["tri_side"], cfg["tri_spp"], cfg["tri_long_spp"]
    for target in cfg["triangles"]:
        scene = run([sys.executable, os.path.join(HERE, "gen.py"), "mesh", out,
                     "--triangles", str(target)]).strip()
        m = re.search(r"mesh_(\d+)\.xml$", scene)
        if not m:
            sys.exit(f"scaling: gen.py mesh printed {scene!r}, not a mesh_N.xml path")
        n = int(m.group(1))
        r["mesh_depth"] = default_max_depth(scene)
        _, t1 = render(scene, os.path.join(out, f"mesh_{n}_1spp.exr"), side, 1)
        samples, tn = render(scene, os.path.join(out, f"mesh_{n}_{spp}spp.exr"), side, spp)
        _, tl = render(scene, os.path.join(out, f"mesh_{n}_{long_spp}spp.exr"), side, long_spp)
        marginal = (tl - t1) / (side * side * (long_spp - 1)) * 1e6
        if marginal <= 0:
            sys.exit(f"scaling: mesh_{n}: {long_spp} spp took {tl} s, not more than 1 spp's "
                     f"{t1} s")
        r["triangles"].append((n, t1, tn, tl, tn / samples * 1e6, marginal))
        print(f"scaling: {n} triangles: {t1:.3f} s at 1 spp, {tn:.3f} s at {spp} spp, "
              f"{tl:.3f} s at {long_spp} spp", file=sys.stderr)

    for t in cfg["threads"]:
        rates = []
        for k in range(cfg["thr_runs"]):
            samples, s = render(CORNELL, os.path.join(out, f"cornell_threads_{t}_{k}.exr"),
                                cfg["thr_side"], cfg["thr_spp"], threads=t)
            rates.append(samples / s * 1e-6)
        r["threads"].append((t, median(rates), rates))
        print(f"scaling: {t} threads: " + ", ".join(f"{x:.3f}" for x in rates) +
              " Msamples/s", file=sys.stderr)

    for side in cfg["resolutions"]:
        samples, s = render(CORNELL, os.path.join(out, f"cornell_res_{side}.exr"), side,
                            cfg["res_spp"])
        r["resolutions"].append((side, s / samples * 1e6))
        print(f"scaling: {side}x{side}: {s:.3f} s", file=sys.stderr)

    for d in cfg["depths"]:
        samples, s = render(CORNELL, os.path.join(out, f"cornell_depth_{d}.exr"),
                            cfg["depth_side"], cfg["depth_spp"], max_depth=d)
        r["depths"].append((d, s / samples * 1e6))
        print(f"scaling: max_depth {d}: {s:.3f} s", file=sys.stderr)

    table = tables(r)
    print(table)
    elapsed = time.time() - start
    print(f"scaling: {elapsed:.0f} s in all", file=sys.stderr)
    if write:
        describe = run(["git", "-C", ROOT, "describe", "--always", "--dirty"]).strip()
        header = (f"Measured {time.strftime('%Y-%m-%d %H:%M UTC', time.gmtime())} by "
                  f"`bench/suite/scaling.py {'--full ' if full else ''}--write OUT_DIR` (the "
                  f"checkout at {describe}, {THREADS} threads but in the thread sweep, "
                  f"{os.cpu_count()} cores, {elapsed:.0f} s in all; `uptime` before: "
                  f"`{uptime_before}`, after: `{run(['uptime']).strip()}`).")
        plot = os.path.join(ROOT, "bench", "plots", "scaling.svg")
        write_results(bm, plot, r, table, header)
        print(f"scaling: wrote the table into {bm} and {plot}", file=sys.stderr)


if __name__ == "__main__":
    main()
