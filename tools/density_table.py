#!/usr/bin/env python3
"""Packing fraction next to the boundary against the interior, per shape and method (issue #5).

Runs the frontpack tool on every shape in shapes/ that has a hole or a reflex corner, with the
methods closed, open and boundary and seeds 1, 2, 3, and writes a markdown table of the means over
the seeds: disks, packing fraction overall, in the interior (farther than 2 rmax from the
boundary) and in the band (within 2 rmax), band - interior, the KS distance by area from the
requested radius distribution, culled disks and the advancing front's time per disk.

Radii: uniform:R,10R (rmax/rmin = 10) with R chosen per shape for about --disks disks (40,000 by
default), from the shape's area as `frontpack info` prints it; the spec used is in the table.

    python3 tools/density_table.py                       # the table on stdout
    python3 tools/density_table.py --out table.md        # ... into a file
    python3 tools/density_table.py --methods boundary    # one method's rows only
    python3 tools/density_table.py --pictures            # docs/img/density-{closed,open,boundary}.png
    python3 tools/density_table.py --sizes --contact-gaps 1e-7 1e-5   # issue #29's table, rattlers at these gaps too
    python3 tools/density_table.py --seam-maps           # docs/img/seams-*.png: where the fronts met

Python 3 standard library only. docs/density.md explains the measures and reads the table.
"""

import argparse
import json
import math
import os
import re
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
METHODS = ("closed", "open", "boundary")
# The boundary method followed by the jam stage (fill --jam, docs/jam.md): --methods boundary+jam.
JAM_METHOD = "boundary+jam"
SEEDS = (1, 2, 3)
RATIO = 10  # rmax / rmin
# The pictures: one concave domain with holes, a few thousand disks so that they are visible.
# The gear rather than the plate: its teeth are narrow (a few rmax), so the sparse band of the
# closed and open forms is plain to see. 540 px keeps each PNG under 300 KB (about 2,000 disks).
PICTURE_SHAPE = "gear.wkt"
PICTURE_RADIUS = "uniform:0.0028,0.028"
PICTURE_SEED = 1
PICTURE_WIDTH = 540


# --- which shapes: a hole or a reflex corner --------------------------------------------------

def parse_wkt_polygons(text):
    """The polygons of a POLYGON or MULTIPOLYGON as lists of rings (lists of (x, y))."""
    tokens = re.findall(r"\(|\)|,|[^\s(),]+", text)
    pos = 0

    def parse(depth_left):
        nonlocal pos
        assert tokens[pos] == "("
        pos += 1
        items = []
        if depth_left == 0:  # a ring: "x y, x y, ..."
            point = []
            while tokens[pos] != ")":
                if tokens[pos] == ",":
                    items.append(tuple(point))
                    point = []
                else:
                    point.append(float(tokens[pos]))
                pos += 1
            items.append(tuple(point))
        else:
            while True:
                items.append(parse(depth_left - 1))
                if tokens[pos] == ",":
                    pos += 1
                    continue
                break
        assert tokens[pos] == ")"
        pos += 1
        return items

    kind = tokens[0].upper()
    pos = 1
    while tokens[pos] != "(":  # e.g. "EMPTY" is not expected; skip modifiers
        pos += 1
    if kind == "POLYGON":
        return [parse(1)]
    if kind == "MULTIPOLYGON":
        return parse(2)
    raise ValueError("unsupported geometry " + kind)


def ring_has_reflex_corner(ring):
    pts = [(p[0], p[1]) for p in ring]
    if pts[0] == pts[-1]:
        pts = pts[:-1]
    n = len(pts)
    area2 = sum(pts[i][0] * pts[(i + 1) % n][1] - pts[(i + 1) % n][0] * pts[i][1] for i in range(n))
    sign = 1 if area2 > 0 else -1
    for i in range(n):
        ax, ay = pts[i - 1]
        bx, by = pts[i]
        cx, cy = pts[(i + 1) % n]
        cross = (bx - ax) * (cy - by) - (by - ay) * (cx - bx)
        if cross * sign < 0:
            return True
    return False


def is_concave(path):
    with open(path) as f:
        polygons = parse_wkt_polygons(f.read())
    return any(len(rings) > 1 or ring_has_reflex_corner(rings[0]) for rings in polygons)


def concave_shapes():
    shapes_dir = os.path.join(ROOT, "shapes")
    names = sorted(n for n in os.listdir(shapes_dir) if n.endswith(".wkt"))
    return [n for n in names if is_concave(os.path.join(shapes_dir, n))]


# --- running the tool ------------------------------------------------------------------------

def run(cmd):
    r = subprocess.run(cmd, stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    if r.returncode != 0:
        sys.exit("command failed (exit %d): %s\n%s" % (r.returncode, " ".join(cmd), r.stderr))
    return r.stdout + r.stderr


def shape_area(tool, shape_path):
    out = run([tool, "info", shape_path])
    m = re.search(r"area:\s*([0-9.eE+-]+)", out)
    if not m:
        sys.exit("no area in `frontpack info %s`:\n%s" % (shape_path, out))
    return float(m.group(1))


def round2(x):
    """x rounded to 2 significant digits."""
    e = math.floor(math.log10(x))
    return round(x / 10 ** e, 1) * 10 ** e


def radius_spec(area, disks):
    # Uniform radii in [r, 10 r]: E[r^2] = (1000 - 1) / (3 * 9) r^2 = 37 r^2; about 0.8 of the
    # area covered.
    r = round2(math.sqrt(0.8 * area / (disks * math.pi * 37.0)))
    return "uniform:%s,%s" % (fmt_num(r), fmt_num(RATIO * r))


def fmt_num(x):
    return ("%.6g" % x)


def fill(tool, shape_path, method, spec, seed, workdir, extra=()):
    js = os.path.join(workdir, "summary.json")
    csv = os.path.join(workdir, "disks.csv")
    jam = ["--jam"] if method.endswith("+jam") else []
    run([tool, "fill", shape_path, "--method", method.removesuffix("+jam"), "--radius", spec, "--seed", str(seed),
         "--json", js, "-q", "-o", csv] + jam + list(extra))
    with open(js) as f:
        return json.load(f), csv


def measure_row(tool, shape, method, spec, workdir):
    path = os.path.join(ROOT, "shapes", shape)
    keys = ("disks", "overall", "interior", "band", "diff", "ks", "seg", "median_ratio", "rattlers", "culled", "us_per_disk")
    acc = {k: 0.0 for k in keys}
    for seed in SEEDS:
        j, _ = fill(tool, path, method, spec, seed, workdir)
        disks = j["disks"]
        acc["disks"] += disks
        acc["overall"] += j["packing_fraction"]
        acc["interior"] += j["interior_fraction"]
        acc["band"] += j["band_fraction"]
        acc["diff"] += j["band_fraction"] - j["interior_fraction"]
        acc["ks"] += j["radius"]["ks_by_area"]
        acc["seg"] += j["segregation_ks_by_area"]
        acc["median_ratio"] += j["band_median_by_area"] / j["inside_median_by_area"]
        acc["rattlers"] += j["rattlers"] / max(disks, 1)
        acc["culled"] += j["certificate"]["culled"]
        acc["us_per_disk"] += 1e6 * j["seconds"]["front"] / max(disks, 1)
    return {k: v / len(SEEDS) for k, v in acc.items()}


def table(tool, shapes, disks, methods, log):
    lines = [
        "| shape | radius | method | disks | overall | interior | band | band - interior | KS by area | segregation KS | band / inside median | rattlers | culled | front µs/disk |",
        "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|",
    ]
    with tempfile.TemporaryDirectory(prefix="density_table_") as workdir:
        for shape in shapes:
            spec = radius_spec(shape_area(tool, os.path.join(ROOT, "shapes", shape)), disks)
            for method in methods:
                t0 = time.monotonic()
                m = measure_row(tool, shape, method, spec, workdir)
                log("%-22s %-9s %-28s %6.0f disks  %.1f s" % (shape, method, spec, m["disks"], time.monotonic() - t0))
                lines.append(
                    "| %s | `%s` | %s | %.0f | %.4f | %.4f | %.4f | %+.4f | %.4f | %.3f | %.3f | %.3f | %.0f | %.2f |"
                    % (shape.removesuffix(".wkt"), spec, method, m["disks"], m["overall"], m["interior"],
                       m["band"], m["diff"], m["ks"], m["seg"], m["median_ratio"], m["rattlers"], m["culled"], m["us_per_disk"]))
    return "\n".join(lines) + "\n"


# --- the size-ratio table (issue #29): every method over the size ratios ------------------------

QUALITY_SHAPES = ("unit_square.wkt", "plate_with_holes.wkt", "gear.wkt", "hole_touching.wkt")
PROFILE_BINS = 6  # the coverage profile's bins [k, k + 1) rmax from the boundary, k < 6


def area_uniform_curve(lo, hi, points=25):
    """A grading curve (radii, by area) uniform by area on [lo, hi]: the curve is linear in
    log(size) between its points, so 25 points make it uniform to within 0.1% in area."""
    pts = [lo + (hi - lo) * i / (points - 1) for i in range(points)]
    return "curve:" + ",".join("%s:%s" % (fmt_num(p), fmt_num(i / (points - 1))) for i, p in enumerate(pts)) + "@radius"


def size_specs(area, disks):
    """(label, spec) for the radius distributions of issue #29, each scaled to about `disks` disks
    covering 0.8 of `area` (from the mean squared radius of each distribution)."""
    def base(mean_square_over_r2):
        return round2(math.sqrt(0.8 * area / (disks * math.pi * mean_square_over_r2)))

    specs = []
    r = base((1 + 1.4 ** 2) / 2)
    specs.append(("bidisperse 1:1.4", "discrete:%s:0.5,%s:0.5" % (fmt_num(r), fmt_num(1.4 * r))))
    for k in (1.4, 2, 3, 5, 10, 100):
        r = base((1 + k + k * k) / 3)  # uniform on [r, k r]: E[r^2] = (1 + k + k^2) r^2 / 3
        specs.append(("uniform %g" % k, "uniform:%s,%s" % (fmt_num(r), fmt_num(k * r))))
    # lognormal, geometric sd 1.5, default bounds median / 1.5^3 .. median * 1.5^3: E[r^2] = median^2 exp(2 s^2)
    s = math.log(1.5)
    r = base(math.exp(2 * s * s))
    specs.append(("lognormal GSD 1.5", "lognormal:%s,1.5" % fmt_num(r)))
    for k in (3, 10):
        r = base(k)  # uniform by area on [r, k r]: number density ~ 1 / r^2, so E[r^2] = k r^2
        specs.append(("uniform by area %g" % k, area_uniform_curve(r, k * r)))
    return specs


def rattlers_at(tool, shape_path, csv, gap, workdir):
    """The share of rattlers (fewer than 3 contacts) when a gap up to `gap` counts as a contact."""
    js = os.path.join(workdir, "stats.json")
    run([tool, "stats", shape_path, csv, "--contact-gap", repr(gap), "--samples", "1000", "--json", js, "-q"])
    with open(js) as f:
        j = json.load(f)
    return j["rattlers"] / max(j["disks"], 1)


def quality_run(tool, shape_path, method, spec, seed, workdir, contact_gaps=()):
    d = tempfile.mkdtemp(dir=workdir)
    j, csv = fill(tool, shape_path, method, spec, seed, d, extra=("--holes",))
    disks = max(j["disks"], 1)
    rmax = j["radius"]["max"]
    interior = j["interior_fraction"]
    profile = [b for b in j["coverage_profile"] if b["to_rmax"] is not None and 1 <= b["from_rmax"] < PROFILE_BINS]
    worst = max((b["fraction"] - interior for b in profile), key=abs, default=0.0)
    median_holes = j["holes"][0]["count"] if j["holes"] else 0
    return {
        "disks": j["disks"], "interior": interior, "band": j["band_fraction"],
        "lec": j["largest_empty_circle"]["radius_upper"] / rmax, "holes": 100.0 * median_holes / disks,
        "profile": worst, "cell_p1": j["cell_coverage"]["p1"], "rattlers": j["rattlers"] / disks,
        "seg": j["segregation_ks_by_area"], "ks": j["radius"]["ks_by_area"],
        "us_per_disk": 1e6 * (j["seconds"]["front"] + j["seconds"].get("jam", 0)) / disks,
        "culled": j["certificate"]["culled"],
        **{"rattlers@%g" % g: rattlers_at(tool, shape_path, csv, g * rmax, d) for g in contact_gaps},
    }


def quality_table(tool, shapes, disks, methods, jobs, log, labels=None, seeds=SEEDS, contact_gaps=()):
    import concurrent.futures
    gaps = "".join(" rattlers, gap %g rmax |" % g for g in contact_gaps)
    lines = [
        "| shape | radii | method | disks | interior | band | largest empty circle / rmax (max) | holes taking a median disk, % of disks | profile 1-6 rmax, worst - interior | cell coverage, 1st percentile | rattlers | segregation KS | KS by area | culled | front µs/disk |" + gaps,
        "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|" + "---:|" * len(contact_gaps),
    ]
    specs_of = {}
    with tempfile.TemporaryDirectory(prefix="quality_table_") as workdir:
        work = []
        for shape in shapes:
            path = os.path.join(ROOT, "shapes", shape)
            specs_of[shape] = [(l, s) for l, s in size_specs(shape_area(tool, path), disks) if not labels or l in labels]
            for label, spec in specs_of[shape]:
                for method in methods:
                    for seed in seeds:
                        work.append((shape, label, method, seed, path, spec))
        with concurrent.futures.ThreadPoolExecutor(max_workers=jobs) as ex:
            runs = list(ex.map(lambda w: quality_run(tool, w[4], w[2], w[5], w[3], workdir, contact_gaps), work))
        rows = {}
        for w, m in zip(work, runs):
            rows.setdefault(w[:3], []).append(m)
        for shape in shapes:
            for label, spec in specs_of[shape]:
                for method in methods:
                    ms = rows[(shape, label, method)]
                    mean = {k: sum(m[k] for m in ms) / len(ms) for k in ms[0]}
                    lec = max(m["lec"] for m in ms)
                    log("%-20s %-20s %-9s %7.0f disks interior %.4f" % (shape, label, method, mean["disks"], mean["interior"]))
                    lines.append(
                        "| %s | %s | %s | %.0f | %.4f | %.4f | %.2f | %.3f | %+.3f | %.3f | %.3f | %.3f | %.4f | %.0f | %.2f |"
                        % (shape.removesuffix(".wkt"), label, method, mean["disks"], mean["interior"], mean["band"], lec,
                           mean["holes"], mean["profile"], mean["cell_p1"], mean["rattlers"], mean["seg"], mean["ks"],
                           mean["culled"], mean["us_per_disk"])
                        + "".join(" %.3f |" % mean["rattlers@%g" % g] for g in contact_gaps))
    specs = "\n".join("- %s: `%s`" % (label, spec) for label, spec in specs_of[shapes[0]])
    return "\n".join(lines) + "\n\nRadius specs on %s (scaled by the square root of the area on the other shapes):\n\n%s\n" % (
        shapes[0].removesuffix(".wkt"), specs)


def pictures(tool, out_dir, log):
    """Closed, open and boundary fills of the same domain, same radii and seed, as PNGs."""
    os.makedirs(out_dir, exist_ok=True)
    shape_path = os.path.join(ROOT, "shapes", PICTURE_SHAPE)
    with tempfile.TemporaryDirectory(prefix="density_pictures_") as workdir:
        for method in METHODS:
            # The commands, as docs/density.md gives them:
            #   frontpack fill shapes/gear.wkt --method M --radius uniform:0.0028,0.028 --seed 1 -o M.csv
            #   frontpack render shapes/gear.wkt M.csv -o docs/img/density-M.png --width 540 --no-histogram
            j, csv = fill(tool, shape_path, method, PICTURE_RADIUS, PICTURE_SEED, workdir)
            png = os.path.join(out_dir, "density-%s.png" % method)
            run([tool, "render", shape_path, csv, "-o", png, "--width", str(PICTURE_WIDTH), "--no-histogram", "-q"])
            log("%s: %d disks, band %.4f, interior %.4f, %d bytes"
                % (png, j["disks"], j["band_fraction"], j["interior_fraction"], os.path.getsize(png)))


# --- the pictures of issue #29: bidisperse 1:1.4, and the seam where the fronts met last ----------

NARROW_SHAPE = "plate_with_holes.wkt"
NARROW_RADIUS = "discrete:0.024:0.5,0.0336:0.5"  # bidisperse 1:1.4, about 2,000 disks
SEAM_RADIUS = "uniform:0.0019,0.019"  # rmax / rmin = 10 on a 10 x 10 square: about 207,000 disks
SEAM_CROP = (4.5, 4.5, 5.5, 5.5)  # the centre, where the four walls' fronts meet last


def quality_pictures(tool, label, out_dir, log):
    """docs/img/quality-{bidisperse,seam}-LABEL.png with this tool: the bidisperse plate, and the
    centre of a 10 x 10 square filled at rmax / rmin = 10 (the disks whose centre lies in the crop,
    drawn in the crop)."""
    os.makedirs(out_dir, exist_ok=True)
    with tempfile.TemporaryDirectory(prefix="quality_pictures_") as workdir:
        plate = os.path.join(ROOT, "shapes", NARROW_SHAPE)
        j, csv = fill(tool, plate, "boundary", NARROW_RADIUS, PICTURE_SEED, workdir)
        png = os.path.join(out_dir, "quality-bidisperse-%s.png" % label)
        run([tool, "render", plate, csv, "-o", png, "--width", "700", "--no-histogram", "-q"])
        log("%s: %d disks, interior %.4f" % (png, j["disks"], j["interior_fraction"]))

        square = os.path.join(workdir, "square.wkt")
        with open(square, "w") as f:
            f.write("POLYGON((0 0,10 0,10 10,0 10,0 0))\n")
        j, csv = fill(tool, square, "boundary", SEAM_RADIUS, PICTURE_SEED, workdir)
        x0, y0, x1, y1 = SEAM_CROP
        crop = os.path.join(workdir, "crop.wkt")
        with open(crop, "w") as f:
            f.write("POLYGON((%g %g,%g %g,%g %g,%g %g,%g %g))\n" % (x0, y0, x1, y0, x1, y1, x0, y1, x0, y0))
        kept = os.path.join(workdir, "crop.csv")
        with open(csv) as src, open(kept, "w") as dst:
            dst.write(src.readline())
            for line in src:
                x, y, r = (float(v) for v in line.split(",")[:3])
                if x0 + r <= x <= x1 - r and y0 + r <= y <= y1 - r:
                    dst.write(line)
        png = os.path.join(out_dir, "quality-seam-%s.png" % label)
        run([tool, "render", crop, kept, "-o", png, "--width", "540", "--no-histogram", "-q"])
        log("%s: %d disks in the square, interior %.4f" % (png, j["disks"], j["interior_fraction"]))


# --- the seams: the cell coverage's map, as a picture -------------------------------------------

SEAM_MAP_RADIUS = "discrete:0.005:0.5,0.007:0.5"  # bidisperse 1:1.4 on the plate: about 45,000 disks
SEAM_MAP_METHODS = ("closed", "boundary", JAM_METHOD)
SEAM_MAP_RANGE = (0.70, 0.86)  # the coverage from dark to light
SEAM_MAP_WIDTH = 540  # pixels


def seam_maps(tool, out_dir, log):
    """docs/img/seams-METHOD.png: the cell coverage's map of the plate at bidisperse 1:1.4, seed 1,
    drawn by `frontpack render --cells`, each cell of 8 rmax coloured from SEAM_MAP_RANGE[0] (dark)
    to [1] (light) on every picture, so that the three compare."""
    os.makedirs(out_dir, exist_ok=True)
    plate = os.path.join(ROOT, "shapes", NARROW_SHAPE)
    cells_range = "%g,%g" % SEAM_MAP_RANGE
    with tempfile.TemporaryDirectory(prefix="seam_maps_") as workdir:
        for method in SEAM_MAP_METHODS:
            #   frontpack fill shapes/plate_with_holes.wkt --method M [--jam] --radius SEAM_MAP_RADIUS --seed 1 --json s.json -o d.csv
            #   frontpack render shapes/plate_with_holes.wkt d.csv --cells --cells-range 0.7,0.86 -o seams-M.png --width 540
            j, csv = fill(tool, plate, method, SEAM_MAP_RADIUS, PICTURE_SEED, workdir)
            c = j["cell_coverage"]
            png = os.path.join(out_dir, "seams-%s.png" % method.replace("+", "-"))
            run([tool, "render", plate, csv, "--cells", "--cells-range", cells_range, "-o", png, "--width",
                 str(SEAM_MAP_WIDTH), "-q"])
            log("%s: %d disks, interior %.4f, cells %d: p1 %.4f, p5 %.4f, median %.4f, sd %.4f"
                % (png, j["disks"], j["interior_fraction"], c["cells"], c["p1"], c["p5"], c["p50"], c["sd"]))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--frontpack", default=os.path.join(ROOT, "build", "release", "tools", "frontpack"),
                    help="the frontpack tool (default: build/release/tools/frontpack)")
    ap.add_argument("--out", help="write the table to this file (default: stdout)")
    ap.add_argument("--disks", type=int, default=40000, help="about this many disks per run (default 40000)")
    ap.add_argument("--shapes", nargs="*", help="these shapes (file names in shapes/) instead of every concave one")
    ap.add_argument("--methods", nargs="*", choices=METHODS + (JAM_METHOD,), default=list(METHODS),
                    help="these methods only (default: the three without the jam stage)")
    ap.add_argument("--specs", nargs="*", help="--sizes: these radius labels only (e.g. 'bidisperse 1:1.4')")
    ap.add_argument("--seeds", nargs="*", type=int, default=list(SEEDS), help="seeds (default 1 2 3)")
    ap.add_argument("--pictures", action="store_true",
                    help="write docs/img/density-{closed,open,boundary}.png (%s, %s, seed %d, %d px) and no table"
                    % (PICTURE_SHAPE, PICTURE_RADIUS, PICTURE_SEED, PICTURE_WIDTH))
    ap.add_argument("--img-dir", default=os.path.join(ROOT, "docs", "img"), help="where --pictures writes")
    ap.add_argument("--sizes", action="store_true",
                    help="the size-ratio table instead (issue #29): bidisperse 1:1.4, uniform 1.4 to 100, lognormal, "
                    "uniform by area; on %s; holes, coverage profile and cells" % ", ".join(QUALITY_SHAPES))
    ap.add_argument("--quality-pictures", metavar="LABEL",
                    help="write docs/img/quality-{bidisperse,seam}-LABEL.png with --frontpack and no table "
                    "(the bidisperse plate and the centre of a 10 x 10 square at rmax / rmin = 10)")
    ap.add_argument("--seam-maps", action="store_true",
                    help="write docs/img/seams-{closed,boundary,boundary-jam}.png, the cell coverage's map of the plate "
                    "at bidisperse 1:1.4 (%s, seed %d), and no table" % (SEAM_MAP_RADIUS, PICTURE_SEED))
    ap.add_argument("--contact-gaps", nargs="*", type=float, default=[],
                    help="--sizes: also the share of rattlers when a gap up to each of these (in rmax) counts as a contact")
    ap.add_argument("--jobs", type=int, default=2, help="runs at a time for --sizes (default 2)")
    ap.add_argument("-q", "--quiet", action="store_true", help="no progress lines on stderr")
    args = ap.parse_args()

    tool = os.path.abspath(args.frontpack)
    if not os.access(tool, os.X_OK):
        sys.exit("no frontpack tool at %s (build it, or give --frontpack)" % tool)

    def log(msg):
        if not args.quiet:
            print(msg, file=sys.stderr, flush=True)

    if args.pictures:
        pictures(tool, args.img_dir, log)
        return
    if args.seam_maps:
        seam_maps(tool, args.img_dir, log)
        return
    if args.quality_pictures:
        quality_pictures(tool, args.quality_pictures, args.img_dir, log)
        return

    t0 = time.monotonic()
    if args.sizes:
        text = quality_table(tool, args.shapes or list(QUALITY_SHAPES), args.disks, args.methods, args.jobs, log,
                             args.specs, tuple(args.seeds), tuple(args.contact_gaps))
    else:
        text = table(tool, args.shapes or concave_shapes(), args.disks, args.methods, log)
    log("total %.0f s" % (time.monotonic() - t0))
    if args.out:
        with open(args.out, "w") as f:
            f.write(text)
    else:
        sys.stdout.write(text)


if __name__ == "__main__":
    main()
