#!/usr/bin/python3
"""DXF against an independent reader and writer (ezdxf, Debian's python3-ezdxf).

1. Kontur writes a document of every curve kind as DXF, both flavours; ezdxf reads the files (its
   audit finds no error), and the curves' lengths and bounding boxes, computed here from ezdxf's own
   geometry (its Bézier decomposition of each SPLINE, the vertices of each LWPOLYLINE and LINE),
   agree with what `kontur-cli info` says of the document within 1e-6 of the units (the polyline
   flavour: with what Kontur reads back from it, and every curve within the tolerance of its polyline).
2. ezdxf writes a DXF (SPLINE with non-uniform knots, LWPOLYLINE, LINE, a bulge, ARC, CIRCLE); Kontur
   imports it and its lengths and boxes agree with ezdxf's geometry (exact entities within 1e-6, arcs,
   which Kontur approximates by cubics within 1e-6, within 1e-5).

Usage: dxf_ezdxf.py KONTUR_CLI DOCUMENT WORKDIR
"""
import json
import math
import os
import subprocess
import sys

import ezdxf
from ezdxf.math import bulge_to_arc
import numpy as np

CLI, DOCUMENT, WORK = sys.argv[1:4]
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def cli(*args):
    run = subprocess.run([CLI, *args], capture_output=True, text=True, env={**os.environ, "LC_ALL": "C.UTF-8"})
    if run.returncode != 0:
        sys.exit(f"kontur-cli {' '.join(args)} failed: {run.stderr}")
    return json.loads(run.stdout)


# Gauss–Legendre nodes on [0, 1] for the length integral of |B'(t)|, adaptively halved.
GL_X, GL_W = np.polynomial.legendre.leggauss(20)
GL_X = (GL_X + 1) / 2
GL_W = GL_W / 2


def bernstein_derivative(ctrl):
    n = len(ctrl) - 1
    return n * (ctrl[1:] - ctrl[:-1])


def de_casteljau(ctrl, t):
    pts = ctrl.copy()
    while len(pts) > 1:
        pts = (1 - t) * pts[:-1] + t * pts[1:]
    return pts[0]


def speed(ctrl, ts):
    d = bernstein_derivative(ctrl)
    return np.array([np.linalg.norm(de_casteljau(d, t)) for t in ts])


def seg_length(ctrl, a=0.0, b=1.0, whole=None, depth=0):
    if len(ctrl) == 2:
        return np.linalg.norm(ctrl[1] - ctrl[0]) * (b - a)
    h = b - a
    est = h * np.dot(GL_W, speed(ctrl, a + h * GL_X)) if whole is None else whole
    m = (a + b) / 2
    left = (m - a) * np.dot(GL_W, speed(ctrl, a + (m - a) * GL_X))
    right = (b - m) * np.dot(GL_W, speed(ctrl, m + (b - m) * GL_X))
    if abs(left + right - est) < 1e-12 or depth > 20:
        return left + right
    return seg_length(ctrl, a, m, left, depth + 1) + seg_length(ctrl, m, b, right, depth + 1)


def seg_box(ctrl):
    """Exact box of a Bézier piece: its ends and the roots of its derivative's components."""
    ts = [0.0, 1.0]
    if len(ctrl) > 2:
        d = bernstein_derivative(ctrl)
        n = len(d) - 1
        for k in range(2):
            # Bernstein → power basis: coefficients of sum d_i C(n,i) t^i (1-t)^(n-i).
            poly = np.zeros(n + 1)
            for i in range(n + 1):
                base = np.polynomial.polynomial.polypow([1, -1], n - i) if n - i > 0 else np.array([1.0])
                term = math.comb(n, i) * d[i][k] * np.concatenate([np.zeros(i), base])
                poly[: len(term)] += term
            if np.any(poly != 0):
                for r in np.polynomial.polynomial.polyroots(poly):
                    if abs(r.imag) < 1e-9 and 0 < r.real < 1:
                        ts.append(r.real)
    pts = np.array([de_casteljau(ctrl, t) for t in ts])
    return pts.min(axis=0), pts.max(axis=0)


def pieces_of(entity):
    """The Bézier pieces (arrays of control points) of an entity, from ezdxf's own geometry."""
    kind = entity.dxftype()
    if kind == "SPLINE":
        spline = entity.construction_tool()
        return [np.array([(p.x, p.y) for p in piece]) for piece in spline.bezier_decomposition()]
    if kind == "LINE":
        return [np.array([(entity.dxf.start.x, entity.dxf.start.y), (entity.dxf.end.x, entity.dxf.end.y)])]
    if kind == "LWPOLYLINE":
        pts = [np.array(p[:2]) for p in entity.get_points("xy")]
        if entity.closed:
            pts.append(pts[0])
        return [np.array([pts[i], pts[i + 1]]) for i in range(len(pts) - 1)]
    raise ValueError(kind)


def measure(pieces):
    length = sum(seg_length(p) for p in pieces)
    boxes = [seg_box(p) for p in pieces]
    lo = np.min([b[0] for b in boxes], axis=0)
    hi = np.max([b[1] for b in boxes], axis=0)
    return length, [lo[0], lo[1], hi[0], hi[1]]


def compare(label, pieces, info, tol):
    length, box = measure(pieces)
    check(abs(length - info["length"]) <= tol, f"{label}: length {length!r} vs Kontur {info['length']!r}")
    check(max(abs(a - b) for a, b in zip(box, info["bbox"])) <= tol, f"{label}: box {box} vs Kontur {info['bbox']}")


def arc_points(center, r, a0, a1):
    """The points of an arc (counter-clockwise from a0 to a1) that bound it: its ends and the
    quarter turns within it."""
    while a1 <= a0:
        a1 += 2 * math.pi
    angles = [a0, a1] + [k * math.pi / 2 for k in range(-8, 16) if a0 < k * math.pi / 2 < a1]
    return np.array([(center[0] + r * math.cos(a), center[1] + r * math.sin(a)) for a in angles])


def read(path):
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    check(not auditor.has_errors, f"{path}: ezdxf's audit found errors")
    return doc


def distance_to_polyline(point, poly):
    a, b = poly[:-1], poly[1:]
    ab = b - a
    t = np.clip(np.einsum("ij,ij->i", point - a, ab) / np.maximum(np.einsum("ij,ij->i", ab, ab), 1e-300), 0, 1)
    return np.min(np.linalg.norm(a + t[:, None] * ab - point, axis=1))


# ---------------------------------------------------------------- 1. Kontur → ezdxf
reference = cli("info", "--accuracy", "1e-12", DOCUMENT)
curves = reference["curves"]
spline_path = os.path.join(WORK, "kontur-spline.dxf")
poly_path = os.path.join(WORK, "kontur-polyline.dxf")
cli("convert", DOCUMENT, spline_path)
cli("convert", "--dxf", "polyline", DOCUMENT, poly_path)

exact = read(spline_path)
check(exact.dxfversion == "AC1015", f"version {exact.dxfversion}")
check(exact.header.get("$INSUNITS") == 4, "$INSUNITS is not 4 (mm)")
entities = list(exact.modelspace())
check(len(entities) == len(curves), f"{len(entities)} entities for {len(curves)} curves")
exact_pieces = []
for entity, info in zip(entities, curves):
    pieces = pieces_of(entity)
    exact_pieces.append(pieces)
    compare(f"spline flavour, {info['name']} ({entity.dxftype()})", pieces, info, 1e-6)
    if entity.dxftype() == "SPLINE":
        check(entity.dxf.degree == max(len(p) - 1 for p in pieces), f"{info['name']}: degree")

flat = read(poly_path)
check(flat.header.get("$INSUNITS") == 4, "polyline flavour: $INSUNITS is not 4 (mm)")
back = cli("info", "--accuracy", "1e-12", poly_path)["curves"]
flat_entities = list(flat.modelspace())
check(len(flat_entities) == len(curves) == len(back), "polyline flavour: one entity per curve")
tolerance = 0.05  # mm, the default
for entity, info, curve_pieces in zip(flat_entities, back, exact_pieces):
    check(entity.dxftype() in ("LWPOLYLINE", "LINE"), f"polyline flavour: {entity.dxftype()}")
    pieces = pieces_of(entity)
    compare(f"polyline flavour, curve {info['index']}", pieces, info, 1e-6)
    poly = np.array([pieces[0][0]] + [p[1] for p in pieces])
    worst = 0.0
    for ctrl in curve_pieces:
        for t in np.linspace(0, 1, 201):
            worst = max(worst, distance_to_polyline(de_casteljau(ctrl, t), poly))
    check(worst <= tolerance + 1e-9, f"polyline flavour, curve {info['index']}: {worst} from the curve")
print(f"Kontur → ezdxf: {len(curves)} curves in both flavours agree")

# ---------------------------------------------------------------- 2. ezdxf → Kontur
doc = ezdxf.new("R2000")
doc.header["$INSUNITS"] = 4
msp = doc.modelspace()
control = [(0, 0), (10, 25), (30, 30), (45, 5), (60, -10), (80, 15), (95, 0)]
msp.add_open_spline(control, degree=3, knots=[0, 0, 0, 0, 0.2, 0.45, 0.5, 1, 1, 1, 1])
msp.add_open_spline([(0, 40), (20, 70), (40, 40), (60, 70), (80, 40)], degree=2, knots=[0, 0, 0, 1, 2.5, 3, 3, 3])
msp.add_lwpolyline([(0, -20), (30, -20), (30, -40), (0, -35)], close=True)
msp.add_line((-10, -10), (100.5, 80.25))
msp.add_lwpolyline([(0, 100, 0, 0, 0.5), (40, 100, 0, 0, 0), (40, 130)], format="xyseb")
msp.add_arc((50, 50), 20, 30, 250)
msp.add_circle((-30, 60), 12.5)
ours = os.path.join(WORK, "ezdxf-written.dxf")
doc.saveas(ours)
imported = cli("info", "--accuracy", "1e-12", ours)
check(imported["units"] == "mm", f"units {imported['units']}")
got = imported["curves"]
written = list(msp)
check(len(got) == len(written), f"Kontur imported {len(got)} curves of {len(written)} entities")
for entity, info in zip(written, got):
    kind = entity.dxftype()
    if kind in ("SPLINE", "LINE") or (kind == "LWPOLYLINE" and not entity.has_arc):
        compare(f"ezdxf {kind}", pieces_of(entity), info, 1e-6)
        continue
    # Arcs: ezdxf's exact length (r·θ) and its box of a fine flattening, against Kontur's cubics.
    if kind == "ARC":
        length = 20 * math.radians(250 - 30)
    elif kind == "CIRCLE":
        length = 2 * math.pi * 12.5
    else:  # the polyline with a bulge: an arc of 4·atan(0.5) over a chord of 40, then a line of 30
        theta = 4 * math.atan(0.5)
        length = 40 / (2 * math.sin(theta / 2)) * theta + 30
    check(abs(length - info["length"]) <= 1e-5, f"ezdxf {kind}: length {length} vs Kontur {info['length']}")
    if kind == "ARC":
        pts = arc_points((50, 50), 20, math.radians(30), math.radians(250))
    elif kind == "CIRCLE":
        pts = arc_points((-30, 60), 12.5, 0, 2 * math.pi)
    else:
        center, a0, a1, r = bulge_to_arc((0, 100), (40, 100), 0.5)
        pts = np.vstack([arc_points((center.x, center.y), r, a0, a1), [(40, 130)]])
    box = [*pts.min(axis=0), *pts.max(axis=0)]
    check(max(abs(a - b) for a, b in zip(box, info["bbox"])) <= 1e-5, f"ezdxf {kind}: box {box} vs {info['bbox']}")
print(f"ezdxf → Kontur: {len(written)} entities agree")

if failures:
    sys.exit(f"{len(failures)} checks failed")
