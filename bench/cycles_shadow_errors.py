#!/usr/bin/env python3
"""Errors of Cycles' shadowed bakes against vlit's exact shadows, one table per asset.

Run by scripts/cycles-shadows-compare.sh, which leaves in DIR: cycles-S.txt (Cycles' bake with
S samples: "x y z nx ny nz r" per face corner, bench/blender_bake.py --shadows), cycles-times.txt
("S seconds" per bake), probe.csv (vlit probe --occluders at the same corners: index,diffuse,...)
and vlit-times.txt (the light stage of `vlit bake --shadows on`, one thread, one line per run).

Errors are per face corner against vlit and relative to the largest vlit value ("top"): the
largest, the 99.9th and 99th percentiles and the root mean square of |Cycles - vlit| / top, over
every corner. The largest error stops falling where a few corners are treated differently by the
two (poles, contact points, creases: docs/shadows.md "Against Blender Cycles with shadows"); the
last two columns repeat the largest error and the 99.9th percentile without the corners of
triangles that touch a pole: a position shared by more than POLE_VALENCE triangles (the centre
of a triangle fan), or a corner of a needle triangle (area below 1e-10 of its longest edge
squared: a lathed mesh's pole split into copies a rounding error apart). The corners come from
Blender's glTF import, three per triangle in face order.

usage: cycles_shadow_errors.py DIR NAME
"""
import math
import os
import sys

POLE_VALENCE = 12  # a position shared by more triangles is a pole (or a fan's centre)


def read_floats(path, column):
    with open(path) as f:
        return [float(line.split()[column]) for line in f if line.strip()]


def pole_positions(path):
    """Positions (as written) of the corners of triangles that touch a pole in a cycles-S.txt file:
    a position shared by more than POLE_VALENCE triangles, or a needle triangle (area below 1e-10
    of its longest edge squared: a pole split into copies a rounding error apart)."""
    with open(path) as f:
        corners = [tuple(line.split()[:3]) for line in f if line.strip()]
    if len(corners) % 3:
        sys.exit("cycles_shadow_errors.py: %s: %d corners, not three per triangle" % (path, len(corners)))
    valence = {}
    for p in corners:
        valence[p] = valence.get(p, 0) + 1
    near = set()
    for i in range(0, len(corners), 3):
        a, b, c = ([float(v) for v in corner] for corner in corners[i:i + 3])
        u = [b[k] - a[k] for k in range(3)]
        v = [c[k] - a[k] for k in range(3)]
        w = [c[k] - b[k] for k in range(3)]
        cross = [u[1] * v[2] - u[2] * v[1], u[2] * v[0] - u[0] * v[2], u[0] * v[1] - u[1] * v[0]]
        needle = 0.5 * math.sqrt(sum(x * x for x in cross)) < 1e-10 * max(sum(x * x for x in e) for e in (u, v, w))
        if needle or any(valence[p] > POLE_VALENCE for p in corners[i:i + 3]):
            near.update(corners[i:i + 3])
    return near, corners


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    out, name = sys.argv[1], sys.argv[2]
    vlit = []
    with open(os.path.join(out, "probe.csv")) as f:
        header = f.readline()
        if not header.startswith("index,diffuse"):
            sys.exit("cycles_shadow_errors.py: %s/probe.csv: unexpected header %r" % (out, header))
        for line in f:
            vlit.append(float(line.split(",")[1]))
    top = max(vlit)
    if not top > 0:
        sys.exit("cycles_shadow_errors.py: vlit's values are all 0: nothing to compare")
    times = {}
    with open(os.path.join(out, "cycles-times.txt")) as f:
        for line in f:
            key, seconds = line.split()
            if key != "import":
                times[int(key)] = float(seconds)
    vlit_runs = read_floats(os.path.join(out, "vlit-times.txt"), 0)
    vlit_time = min(vlit_runs)
    poles, positions = pole_positions(os.path.join(out, "cycles-%d.txt" % min(times)))
    away = [p not in poles for p in positions]
    rows = []
    for samples in sorted(times):
        cycles = read_floats(os.path.join(out, "cycles-%d.txt" % samples), 6)
        if len(cycles) != len(vlit):
            sys.exit("cycles_shadow_errors.py: %d Cycles corners but %d probe points" % (len(cycles), len(vlit)))
        errors = sorted(abs(c - v) / top for c, v in zip(cycles, vlit))
        rms = math.sqrt(sum(e * e for e in errors) / len(errors))
        p99 = errors[min(len(errors) - 1, int(0.99 * len(errors)))]
        p999 = errors[min(len(errors) - 1, int(0.999 * len(errors)))]
        kept = sorted(abs(c - v) / top for c, v, k in zip(cycles, vlit, away) if k)
        rows.append((samples, times[samples], errors[-1], p999, p99, rms, kept[-1],
                     kept[min(len(kept) - 1, int(0.999 * len(kept)))]))
    print("%s: %d corners (%d at triangles touching a pole), top %.6g; vlit exact shadows, light stage, one thread: "
          "%.3f s (best of %d runs)\n" % (name, len(vlit), away.count(False), top, vlit_time, len(vlit_runs)))
    print("| Cycles samples | Cycles time (s) | max error / top | 99.9th percentile / top | 99th percentile / top "
          "| RMS / top | Cycles time / vlit time | max, away from poles | 99.9th, away from poles |")
    print("|---|---|---|---|---|---|---|---|---|")
    for samples, seconds, largest, p999, p99, rms, kept_max, kept_p999 in rows:
        print("| %d | %.2f | %.2e | %.2e | %.2e | %.2e | %.1f | %.2e | %.2e |"
              % (samples, seconds, largest, p999, p99, rms, seconds / vlit_time, kept_max, kept_p999))
    write_plot(out, name, rows, vlit_time)


def write_plot(out, name, rows, vlit_time):
    """DIR/plot.gp: Cycles' errors against its time over vlit's (log-log), for gnuplot."""
    with open(os.path.join(out, "plot.gp"), "w") as f:
        f.write("set terminal pngcairo size 720,480 font ',10'\n")
        f.write("set output 'cycles-vs-vlit.png'\n")
        f.write("set title \"%s: Cycles with shadows against vlit's exact shadows (one thread each)\"\n" % name)
        f.write("set logscale xy\nset grid\nset key top right\n")
        f.write("set xlabel \"Cycles' time / vlit's time (samples 1 ... %d)\"\n" % rows[-1][0])
        f.write("set ylabel 'error / largest vlit value'\n")
        f.write("set arrow from 1, graph 0 to 1, graph 1 nohead dashtype 2\n")
        f.write("set label \"vlit: exact, at its time\" at 1, graph 0.05 offset 0.5, 0\n")
        columns = [(6, "largest, away from poles"), (7, "99.9th percentile, away from poles"), (4, "99th percentile"),
                   (5, "RMS")]  # indices into a row of main()
        f.write("plot " + ", \\\n     ".join("'-' using 1:2 with linespoints title '%s'" % t for _, t in columns) + "\n")
        for column, _ in columns:
            for row in rows:
                f.write("%.6g %.6g\n" % (row[1] / vlit_time, row[column]))
            f.write("e\n")


if __name__ == "__main__":
    main()
