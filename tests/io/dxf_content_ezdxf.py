#!/usr/bin/python3
"""What real CAD files hold beyond plain entities, against ezdxf (Debian's python3-ezdxf) as the oracle.

ezdxf writes small drawings: a title block of nested blocks (INSERTs with base points, scales, a
rotation and a mirror), a MINSERT array, hatches whose outline exists only as the hatch (polyline and
edge paths: lines, counter-clockwise and clockwise arcs, an elliptic arc, a spline), an ellipse whose
end parameter is written with 12 digits (6.28318530718), and a mixed file with entities Kontur does
not draw (TEXT, MTEXT, 3DFACE, a polyface mesh, a fit-point SPLINE), and kontur-cli's ASTM D6673
(AAMA) export of a traced piece with its allowance. `kontur-cli info` reads each;
its curves' lengths and bounding boxes agree, curve by curve within 1e-6, with ezdxf's own geometry
(INSERTs placed by ezdxf's insertion matrices, composed for nested blocks; entities and hatch paths
by ezdxf.path; lengths of ezdxf's flattening at 1e-7), and what it skipped is what the file holds.

Usage: dxf_content_ezdxf.py KONTUR_CLI WORKDIR. Exits 77 (skipped) when ezdxf is not installed.
"""
import json
import math
import os
import subprocess
import sys

try:
    import ezdxf
    from ezdxf import path as ezpath
    from ezdxf.math import BoundingBox
except ImportError:
    print("SKIP: python3-ezdxf is not installed (packaging/bootstrap installs it)")
    sys.exit(77)

# ezdxf's paths draw an elliptic arc as one cubic per quarter by default (2e-4 of the radius off); as
# an oracle it must be exact to far below the comparison's 1e-6: 256 cubics per arc (1e-13 off).
import ezdxf.path.tools as ez_tools

_cubics = ez_tools.cubic_bezier_from_ellipse
ez_tools.cubic_bezier_from_ellipse = lambda ellipse, segments=1: _cubics(ellipse, 256)

CLI, WORK = sys.argv[1:3]
failures = []


def check(ok, what):
    if not ok:
        failures.append(what)
        print("FAIL:", what)


def info(path, *options):
    run = subprocess.run([CLI, "info", "--accuracy", "1e-10", *options, path], capture_output=True, text=True,
                         env={**os.environ, "LC_ALL": "C.UTF-8"})
    if run.returncode != 0:
        sys.exit(f"kontur-cli info {path} failed: {run.stderr}")
    return json.loads(run.stdout), run.stderr


def flat(paths):
    """Length and box of ezdxf paths, flattened within 1e-7."""
    length = 0.0
    box = BoundingBox()
    for p in paths:
        pts = list(p.flattening(1e-7))
        box.extend(pts)
        length += sum((b - a).magnitude for a, b in zip(pts, pts[1:]))
    return length, box


def exploded(entity, matrix=None):
    """The drawable entities of an entity with the matrix that places them: INSERTs (MINSERT arrays
    too) exploded recursively by composing ezdxf's own insertion matrices (Insert.matrix44), which
    keeps what nested non-uniform scales make of a circle (a sheared ellipse) exact."""
    if entity.dxftype() == "INSERT":
        out = []
        block = entity.doc.blocks.get(entity.dxf.name)
        for insert in entity.multi_insert() if entity.mcount > 1 else [entity]:
            m = insert.matrix44() if matrix is None else insert.matrix44() @ matrix
            for child in block:
                out += exploded(child, m)
        return out
    return [(entity, matrix)]


def oracle(doc):
    """One (length, box) per curve Kontur should make, in ezdxf's terms."""
    curves = []
    for e in doc.modelspace():
        for x, m in exploded(e):
            paths = []
            if x.dxftype() == "HATCH":
                paths = [ezpath.from_hatch_boundary_path(bp, ocs=x.ocs(), elevation=0) for bp in x.paths]
            elif x.dxftype() == "POLYLINE" and (x.is_poly_face_mesh or x.is_polygon_mesh):
                continue  # surfaces: Kontur skips them
            elif x.dxftype() == "SPLINE" and x.control_point_count() == 0:
                continue  # fit points only: Kontur skips it
            elif x.dxftype() in ("LINE", "LWPOLYLINE", "ARC", "CIRCLE", "ELLIPSE", "SPLINE", "POLYLINE"):
                paths = [ezpath.make_path(x)]
            for p in paths:
                curves.append(flat([p if m is None else p.transform(m)]))
    return curves


def compare(label, doc, path, *options):
    expected = sorted(oracle(doc), key=lambda c: (round(c[0], 4), round(c[1].extmin.x, 4)))
    got, stderr = info(path, *options)
    got = sorted(got["curves"], key=lambda c: (round(c["length"], 4), round(c["bbox"][0], 4)))
    check(len(got) == len(expected), f"{label}: {len(got)} curves, ezdxf {len(expected)}")
    for k, ((length, box), c) in enumerate(zip(expected, got)):
        check(abs(length - c["length"]) <= 1e-6 * max(1.0, length),
              f"{label} curve {k}: length {c['length']!r}, ezdxf {length!r}")
        want = [box.extmin.x, box.extmin.y, box.extmax.x, box.extmax.y]
        check(max(abs(a - b) for a, b in zip(want, c["bbox"])) <= 1e-6 * max(1.0, max(map(abs, want))),
              f"{label} curve {k}: box {c['bbox']}, ezdxf {want}")
    return stderr


# 1. Nested blocks with base points, non-uniform and negative scales, rotations; a MINSERT array.
doc = ezdxf.new("R2000", units=4)
inner = doc.blocks.new("INNER", base_point=(1, 1))
inner.add_line((1, 1), (3, 1.5))
inner.add_circle((2, 3), 0.75)
inner.add_lwpolyline([(0, 0, 0, 0, 0.4), (2, 0), (2, 1)], format="xyseb", close=True)
outer = doc.blocks.new("OUTER", base_point=(-1, 0.5))
outer.add_blockref("INNER", (10, 0), dxfattribs={"xscale": 2, "yscale": 0.5, "rotation": 90})
outer.add_arc((0, 0), 4, 10, 250)
outer.add_ellipse((5, 5), major_axis=(3, 1), ratio=0.4, start_param=0.3, end_param=4.0)
msp = doc.modelspace()
msp.add_blockref("OUTER", (100, 50), dxfattribs={"xscale": 1.5, "yscale": -3, "rotation": 30, "layer": "Front"})
grid = msp.add_blockref("INNER", (5, 6), dxfattribs={"xscale": 2, "yscale": 2, "rotation": 45})
grid.grid(size=(2, 3), spacing=(20, 10))
doc.saveas(os.path.join(WORK, "blocks.dxf"))
compare("blocks", doc, os.path.join(WORK, "blocks.dxf"))
got, _ = info(os.path.join(WORK, "blocks.dxf"))
check(len(got["curves"]) == 5 + 6 * 3, f"blocks: {len(got['curves'])} curves, the blocks have 5 + 6 · 3")
check(sum(c["name"] == "Front" for c in got["curves"]) == 5, "blocks: the INSERT's layer is not its content's")

# The same with uniform scales (mirrored too), where ezdxf keeps every entity whole: curve by curve.
doc = ezdxf.new("R2000", units=4)
inner = doc.blocks.new("INNER", base_point=(1, 1))
inner.add_line((1, 1), (3, 1.5))
inner.add_circle((2, 3), 0.75)
inner.add_lwpolyline([(0, 0, 0, 0, 0.4), (2, 0), (2, 1)], format="xyseb", close=True)
outer = doc.blocks.new("OUTER", base_point=(-1, 0.5))
outer.add_blockref("INNER", (10, 0), dxfattribs={"xscale": 2, "yscale": 2, "rotation": 90})
outer.add_arc((0, 0), 4, 10, 250)
outer.add_ellipse((5, 5), major_axis=(3, 1), ratio=0.4, start_param=0.3, end_param=4.0)
msp = doc.modelspace()
msp.add_blockref("OUTER", (100, 50), dxfattribs={"xscale": -1.5, "yscale": 1.5, "rotation": 30})
grid = msp.add_blockref("INNER", (5, 6), dxfattribs={"xscale": 2, "yscale": 2, "rotation": 45})
grid.grid(size=(2, 3), spacing=(20, 10))
doc.saveas(os.path.join(WORK, "blocks-uniform.dxf"))
compare("uniform blocks", doc, os.path.join(WORK, "blocks-uniform.dxf"))

# 2. Hatches whose outline exists only as the hatch.
doc = ezdxf.new("R2000", units=4)
msp = doc.modelspace()
hatch = msp.add_hatch(color=3)
hatch.paths.add_polyline_path([(0, 0, 0), (10, 0, 1), (10, 10, 0), (0, 10, 0)], is_closed=True)
hatch = msp.add_hatch(color=4)
edges = hatch.paths.add_edge_path()
edges.add_line((20, 0), (30, 0))
edges.add_line((30, 0), (30, 10))
edges.add_arc((25, 10), 5, 0, 180, ccw=True)
edges.add_line((20, 10), (20, 0))
hatch = msp.add_hatch(color=5)
edges = hatch.paths.add_edge_path()
edges.add_line((40, 0), (50, 0))
edges.add_line((50, 0), (50, 10))
edges.add_arc((45, 10), 5, 180, 360, ccw=False)  # clockwise from (50, 10) through (45, 5)
edges.add_line((40, 10), (40, 0))
hatch = msp.add_hatch(color=6)
edges = hatch.paths.add_edge_path()
edges.add_ellipse((70, 0), major_axis=(4, 2), ratio=0.5, start_angle=0, end_angle=180, ccw=True)
edges.add_line((70 - 4, 0 - 2), (70 + 4, 0 + 2))
hatch = msp.add_hatch(color=7)
edges = hatch.paths.add_edge_path()
edges.add_spline(control_points=[(80, 0), (81, 3), (84, 4), (86, 1), (88, 0)], degree=3,
                 knot_values=[0, 0, 0, 0, 0.4, 1, 1, 1, 1])
edges.add_line((88, 0), (80, 0))
doc.saveas(os.path.join(WORK, "hatches.dxf"))
compare("hatches", doc, os.path.join(WORK, "hatches.dxf"))

# 3. The 800 × 600 ellipse with its end parameter written with 12 significant digits.
doc = ezdxf.new("R2000", units=4)
doc.modelspace().add_ellipse((0, 0), major_axis=(400, 0), ratio=0.75, start_param=0, end_param=2 * math.pi)
doc.saveas(os.path.join(WORK, "ellipse.dxf"))
with open(os.path.join(WORK, "ellipse.dxf")) as f:
    text = f.read()
exact = " 42\n" + repr(2 * math.pi) + "\n"
check(exact in text, "ellipse: ezdxf wrote its end parameter differently than expected")
with open(os.path.join(WORK, "ellipse-rounded.dxf"), "w") as f:
    f.write(text.replace(exact, " 42\n6.28318530718\n"))
rounded = ezdxf.readfile(os.path.join(WORK, "ellipse-rounded.dxf"))
compare("rounded ellipse", rounded, os.path.join(WORK, "ellipse-rounded.dxf"))
got, _ = info(os.path.join(WORK, "ellipse-rounded.dxf"))
check(got["curves"][0]["closed"], "rounded ellipse: not closed")

# 4. A mixed file: what Kontur cannot draw is skipped and counted, the rest read.
doc = ezdxf.new("R2000", units=4)
msp = doc.modelspace()
msp.add_text("Front piece")
msp.add_text("Cut 2")
msp.add_mtext("Grain line")
msp.add_3dface([(0, 0, 0), (1, 0, 0), (1, 1, 1), (0, 1, 1)])
mesh = msp.add_polyface()
mesh.append_face([(0, 0, 0), (1, 0, 0), (1, 1, 0)])
msp.add_spline(fit_points=[(0, 0), (1, 2), (3, 1), (4, 0)])
msp.add_line((0, 0), (25, 0))
msp.add_circle((10, 10), 3)
doc.saveas(os.path.join(WORK, "mixed.dxf"))
stderr = compare("mixed", doc, os.path.join(WORK, "mixed.dxf"))
check("not drawn: 3 texts, 2 3D objects, 1 spline given only by fit points or weights" in stderr,
      f"mixed: stderr says {stderr!r}")

# 5. Without $INSUNITS the units are the ones asked for; ezdxf's files name theirs.
doc = ezdxf.new("R2000", units=0)
doc.modelspace().add_line((0, 0), (1, 0))
doc.saveas(os.path.join(WORK, "unitless.dxf"))
got, _ = info(os.path.join(WORK, "unitless.dxf"), "--units", "cm")
check(got["units"] == "cm", f"unitless: units {got['units']}")
doc = ezdxf.new("R2000", units=4)
doc.modelspace().add_line((0, 0), (1, 0))
doc.saveas(os.path.join(WORK, "mm.dxf"))
got, _ = info(os.path.join(WORK, "mm.dxf"), "--units", "cm")
check(got["units"] == "mm", f"mm file: units {got['units']}")

# 6. ASTM D6673 (AAMA): a traced piece with its seam allowance and a piece without, exported by
# kontur-cli --aama; ezdxf finds one block per piece on the standard's layers (1 cut line, 14 sew
# line, the "Piece Name:" text; no grain line 7, since the pieces have none, and kontur-cli says so),
# each inserted once at the origin, with the geometry
# of the document's curves within 1e-6 mm (exact splines) or of what Kontur reads back (polylines);
# Kontur reads the pieces back by block and layer.
def run_cli(*args):
    run = subprocess.run([CLI, *args], capture_output=True, text=True, env={**os.environ, "LC_ALL": "C.UTF-8"})
    if run.returncode != 0:
        sys.exit(f"kontur-cli {' '.join(args)} failed: {run.stderr}")
    return run


with open(os.path.join(WORK, "pieces.txt"), "w") as f:
    f.write('curve composite closed\nname "Front"\n0 0\n100 0\n120 80\n50 140\n-10 90\n'
            'curve composite closed\nname "Back"\n300 0\n380 10\n360 90\n290 70\n')
run_cli("convert", os.path.join(WORK, "pieces.txt"), os.path.join(WORK, "pieces.kontur"))
with open(os.path.join(WORK, "pieces.kontur")) as f:
    document = json.load(f)
document["units"] = "mm"
with open(os.path.join(WORK, "pieces.kontur"), "w") as f:
    json.dump(document, f)
run_cli("offset", "--curve", "0", "--distance", "10", os.path.join(WORK, "pieces.kontur"),
        os.path.join(WORK, "pieces-sa.kontur"))
source, _ = info(os.path.join(WORK, "pieces-sa.kontur"))
check([c["name"] for c in source["curves"]][:2] == ["Front", "Back"], "AAMA: the document's curves")
front, back, allowance = source["curves"]
for flavour in ("spline", "polyline"):
    path = os.path.join(WORK, f"aama-{flavour}.dxf")
    converted = run_cli("convert", "--aama", "--dxf", flavour, os.path.join(WORK, "pieces-sa.kontur"), path)
    check("no grain line written" in converted.stderr and "Front" in converted.stderr,
          f"AAMA {flavour}: the missing grainlines said: {converted.stderr!r}")
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    check(not auditor.errors and not auditor.fixes, f"AAMA {flavour}: ezdxf's audit {auditor.errors} {auditor.fixes}")
    blocks = {b.name: b for b in doc.blocks if not b.name.startswith("*")}
    check(sorted(blocks) == ["Back", "Front"], f"AAMA {flavour}: blocks {sorted(blocks)}")
    inserts = [e for e in doc.modelspace()]
    check(sorted((e.dxftype(), e.dxf.name, tuple(e.dxf.insert)) for e in inserts) ==
          [("INSERT", "Back", (0, 0, 0)), ("INSERT", "Front", (0, 0, 0))], f"AAMA {flavour}: inserts")
    read_back, stderr = info(path)
    kontur = {c["name"]: c for c in read_back["curves"]}
    # Pieces back: the sew line (else the cut line) is the piece, the cut line around it its allowance.
    check(sorted(kontur) == ["Back", "Front", "Front cut line"], f"AAMA {flavour}: Kontur reads {sorted(kontur)}")
    check("not drawn" not in stderr, f"AAMA {flavour}: the texts are the pieces': stderr {stderr!r}")
    for name, piece, cut, sew in (("Front", blocks.get("Front"), allowance, front),
                                  ("Back", blocks.get("Back"), back, None)):
        if piece is None:
            continue
        by_layer = {}
        for e in piece:
            by_layer.setdefault(e.dxf.layer, []).append(e)
        texts = [e.dxf.text for e in by_layer.get("1", []) if e.dxftype() == "TEXT"]
        check(f"Piece Name: {name}" in texts, f"AAMA {flavour} {name}: texts {texts}")
        check("7" not in by_layer, f"AAMA {flavour} {name}: no grain line the piece does not have")
        check(("14" in by_layer) == (sew is not None), f"AAMA {flavour} {name}: sew line layer")
        for layer, curve in (("1", cut), ("14", sew)):
            if curve is None:
                continue
            shapes = [e for e in by_layer.get(layer, []) if e.dxftype() != "TEXT"]
            check(len(shapes) == 1, f"AAMA {flavour} {name}: layer {layer} holds {len(shapes)} curves")
            if not shapes:
                continue
            length, box = flat([ezpath.make_path(shapes[0])])
            want = [box.extmin.x, box.extmin.y, box.extmax.x, box.extmax.y]
            role = "cut line" if layer == "1" else "sew line"
            # What Kontur reads back is what ezdxf reads, to the last digits.
            got = kontur[f"{name} cut line" if layer == "1" and sew is not None else name]
            check(abs(got["length"] - length) <= 1e-6 and max(abs(a - b) for a, b in zip(got["bbox"], want)) <= 1e-6,
                  f"AAMA {flavour} {name} {role}: Kontur {got['length']} {got['bbox']}, ezdxf {length} {want}")
            # The exact flavour is the document's curve; the polylines lie within 0.05 mm of it.
            slack = 1e-6 if flavour == "spline" else 0.05
            check(max(abs(a - b) for a, b in zip(curve["bbox"], want)) <= slack,
                  f"AAMA {flavour} {name} {role}: box {want}, document {curve['bbox']}")
            if flavour == "spline":
                check(abs(curve["length"] - length) <= 1e-6,
                      f"AAMA {flavour} {name} {role}: length {length}, document {curve['length']}")

# 7. A piece with every mark (size, quantity, material, fold, grainline, notches of each kind and an
# angle, drill holes) and its allowance, traced at 30°: ezdxf finds each on the standard's layer (1
# texts, 4 notches as POINTs on the cut line with their direction as the angle, 81 castle and 84 V
# notches, 6 the mirror line, 7 the grain line, 13 drill holes, 14 the sew line, nothing on a layer the
# standard gives another meaning); kontur-cli reads the file back into the same marks.
AAMA_LAYERS = {"1": "cut line and text", "4": "notch", "6": "mirror line", "7": "grain line",
               "8": "internal line", "13": "drill hole", "14": "sew line", "81": "castle notch",
               "84": "V notch"}
turn = math.radians(30)


def turned(x, y):
    return [x * math.cos(turn) - y * math.sin(turn) + 50, x * math.sin(turn) + y * math.cos(turn) + 20]


corners = [turned(0, 0), turned(200, 0), turned(200, 400), turned(0, 400)]
points = []
for k in range(4):
    a, b = corners[k], corners[(k + 1) % 4]
    points += [a, [a[0] + (b[0] - a[0]) / 3, a[1] + (b[1] - a[1]) / 3],
               [a[0] + 2 * (b[0] - a[0]) / 3, a[1] + 2 * (b[1] - a[1]) / 3]]
marks = {"size": "38", "quantity": 2, "material": "Wool", "fold": [corners[3], corners[0]],
         "grainline": [turned(100, 50), turned(100, 350)],
         "notches": [{"at": 80.0, "kind": "slit", "angle": 0}, {"at": 250.5, "kind": "v", "angle": 0},
                     {"at": 700.25, "kind": "castle", "angle": 20}],
         "drillHoles": [turned(60, 300), turned(140, 300)], "seamWidths": [30]}
bodice = {"format": "kontur", "version": 3, "units": "mm", "curves": [
    {"kind": "composite", "name": "Bodice", "closed": True, "points": points, "nodeTypes": ["corner"] * 4,
     "settings": {"piece": marks}}]}
with open(os.path.join(WORK, "bodice.kontur"), "w") as f:
    json.dump(bodice, f)
run_cli("offset", "--curve", "0", "--distance", "10", os.path.join(WORK, "bodice.kontur"),
        os.path.join(WORK, "bodice-sa.kontur"))
# kontur-cli convert keeps the seams' widths (and writes the document as it read it).
run_cli("convert", os.path.join(WORK, "bodice-sa.kontur"), os.path.join(WORK, "bodice-copy.kontur"))
with open(os.path.join(WORK, "bodice-copy.kontur")) as f:
    copied = json.load(f)["curves"][0]["settings"]["piece"]
check(copied.get("seamWidths") == [30], f"bodice: convert keeps the seam widths: {copied.get('seamWidths')}")
for flavour in ("spline", "polyline"):
    path = os.path.join(WORK, f"bodice-{flavour}.dxf")
    converted = run_cli("convert", "--aama", "--dxf", flavour, os.path.join(WORK, "bodice-sa.kontur"), path)
    check("grain" not in converted.stderr, f"bodice {flavour}: no warning: {converted.stderr!r}")
    doc = ezdxf.readfile(path)
    auditor = doc.audit()
    check(not auditor.errors and not auditor.fixes, f"bodice {flavour}: ezdxf's audit {auditor.errors}")
    block = doc.blocks.get("Bodice")
    check(block is not None, f"bodice {flavour}: its block")
    by_layer = {}
    for e in block:
        by_layer.setdefault(e.dxf.layer, []).append(e)
    check(set(by_layer) <= set(AAMA_LAYERS), f"bodice {flavour}: layers {sorted(by_layer)}")
    texts = sorted(e.dxf.text for e in by_layer.get("1", []) if e.dxftype() == "TEXT")
    check(texts == sorted(["Piece Name: Bodice", "Size: 38", "Quantity: 2", "Material: Wool",
                           "Annotation: On fold"]), f"bodice {flavour}: texts {texts}")
    grain = by_layer.get("7", [])
    check([e.dxftype() for e in grain] == ["LINE"] and
          math.dist(tuple(grain[0].dxf.start)[:2], marks["grainline"][0]) <= 1e-9 and
          math.dist(tuple(grain[0].dxf.end)[:2], marks["grainline"][1]) <= 1e-9, f"bodice {flavour}: grain line")
    mirror = by_layer.get("6", [])
    check([e.dxftype() for e in mirror] == ["LINE"] and math.dist(tuple(mirror[0].dxf.start)[:2], corners[3]) <= 1e-9,
          f"bodice {flavour}: mirror line")
    holes = sorted(tuple(e.dxf.location)[:2] for e in by_layer.get("13", []) if e.dxftype() == "POINT")
    check(len(holes) == 2 and all(min(math.dist(h, m) for m in marks["drillHoles"]) <= 1e-9 for h in holes),
          f"bodice {flavour}: drill holes {holes}")
    # Notches: POINTs on the cut line (10 mm outside the sew line), pointing into the piece.
    cut = [e for e in by_layer.get("1", []) if e.dxftype() != "TEXT"]
    cut_path = ezpath.make_path(cut[0])
    cut_pts = list(cut_path.flattening(1e-7))
    notches = [e for e in by_layer.get("4", []) if e.dxftype() == "POINT"]
    check(len(notches) == 3, f"bodice {flavour}: {len(notches)} notches")

    def off_cut(p):
        best = math.inf
        for a, b in zip(cut_pts, cut_pts[1:]):
            d = (b - a)
            t = max(0.0, min(1.0, ((p[0] - a.x) * d.x + (p[1] - a.y) * d.y) / max(d.magnitude ** 2, 1e-300)))
            best = min(best, math.dist(p, (a.x + t * d.x, a.y + t * d.y)))
        return best

    for e in notches:
        at = tuple(e.dxf.location)[:2]
        check(off_cut(at) <= 1e-6, f"bodice {flavour}: notch {at} off the cut line by {off_cut(at)}")
    # Square notches point along the side's inward normal: the bottom side runs at 30°, so 120°; the
    # right side at 120°, so 210°; the top side at 210°, its notch turned 20° from 300°: 320°.
    angles = sorted(e.dxf.angle % 360 for e in notches)
    check(len(angles) == 3 and all(abs(a - b) <= 1e-6 for a, b in zip(angles, [120.0, 210.0, 320.0])),
          f"bodice {flavour}: notch angles {angles}")
    # ASTM D6673's notch kinds: 80 T, 81 castle, 82 check, 83 U, 84 V.
    kinds = {layer: len(by_layer.get(layer, [])) for layer in ("80", "81", "82", "83", "84")}
    check(kinds == {"80": 0, "81": 1, "82": 0, "83": 0, "84": 1}, f"bodice {flavour}: notch kinds {kinds}")
    # Back into Kontur: the same marks.
    back = os.path.join(WORK, f"bodice-{flavour}.kontur")
    run_cli("convert", path, back)
    with open(back) as f:
        curves = json.load(f)["curves"]
    check([c["name"] for c in curves] == ["Bodice", "Bodice cut line"], f"bodice {flavour}: {[c['name'] for c in curves]}")
    got = curves[0].get("settings", {}).get("piece", {})
    for key in ("size", "quantity", "material"):
        check(got.get(key) == marks[key], f"bodice {flavour}: {key} {got.get(key)!r}")
    for key in ("fold", "grainline"):
        check(all(math.dist(p, q) <= 1e-9 for p, q in zip(got.get(key, [[math.inf] * 2] * 2), marks[key])),
              f"bodice {flavour}: {key} {got.get(key)}")
    check(len(got.get("notches", [])) == 3 and all(
        n["kind"] == m["kind"] and abs(n["at"] - m["at"]) <= 1e-6 and abs(n["angle"] - m["angle"]) <= 1e-6
        for n, m in zip(got["notches"], marks["notches"])), f"bodice {flavour}: notches {got.get('notches')}")
    check(len(got.get("drillHoles", [])) == 2, f"bodice {flavour}: drill holes {got.get('drillHoles')}")
    seam = curves[1].get("settings", {}).get("seamAllowance", {})
    check(seam.get("source") == 0 and abs(seam.get("distance", 0) - 10) <= 1e-6,
          f"bodice {flavour}: the cut line is the allowance: {seam}")
    # The hem (the first seam) 30 mm, the others the allowance's 10: the cut line gives the width back.
    widths = got.get("seamWidths", [])
    check(len(widths) == 1 and abs(widths[0] - 30) <= 1e-6, f"bodice {flavour}: seam widths {widths}")

if failures:
    sys.exit(f"{len(failures)} failure(s)")
print("all agree with ezdxf")
