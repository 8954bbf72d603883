#!/usr/bin/python3
"""DXF against an independent reader and writer (ezdxf, Debian's python3-ezdxf).

1. Kontur writes a document of every curve kind as DXF, both flavours; ezdxf reads the files (its
   audit finds no error), and the curves' lengths and bounding boxes, computed here from ezdxf's own
   geometry (its Bézier decomposition of each SPLINE, the vertices of each LWPOLYLINE and LINE),
   agree with what `kontur-cli info` says of the document within 1e-6 of the units (the polyline
   flavour: with what Kontur reads back from it, and every curve within the tolerance of its polyline).
   Both are complete AutoCAD 2000 drawings: ezdxf loads them strictly (not recovering), its auditor
   finds no error and makes no fix, every entity, table, record, block and object has its handle
   and an owner that exists, and the tables, blocks and objects a drawing needs are there.
2. The same document with its curves named (refused characters, a duplicate regardless of case, Latvian,
   Cyrillic) and coloured: each name one layer (a duplicate regardless of case shares it), named after
   it (decoded by ezdxf from the file's code page), the entity's true colour the curve's, the layer's
   ACI the nearest to its first curve's.
3. ezdxf writes a DXF (SPLINE with non-uniform knots, LWPOLYLINE, LINE, a bulge, ARC, CIRCLE); Kontur
   imports it and its lengths and boxes agree with ezdxf's geometry (exact entities within 1e-6, arcs,
   which Kontur approximates by cubics within 1e-6, within 1e-5).

Usage: dxf_ezdxf.py KONTUR_CLI DOCUMENT WORKDIR
"""
import colorsys
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
    check(not auditor.has_errors, f"{path}: ezdxf's audit found errors: {[e.message for e in auditor.errors]}")
    return doc


def check_structure(path):
    """A complete R2000 drawing, as ezdxf loads it strictly and as the file says."""
    doc = ezdxf.readfile(path)  # strict: raises on a structure error
    auditor = doc.audit()
    check(not auditor.has_errors and not auditor.has_fixes,
          f"{path}: audit {[e.message for e in auditor.errors]} fixes {[e.message for e in auditor.fixes]}")
    check(doc.dxfversion == "AC1015", f"{path}: version {doc.dxfversion}")
    seed = int(doc.header["$HANDSEED"], 16)
    # The file's own sections, tables and objects, read tag by tag (not through ezdxf's documents,
    # which make what is missing).
    from ezdxf.lldxf.tagger import ascii_tags_loader
    with open(path, encoding="latin-1") as f:  # the tags only; the names are ASCII or in a code page
        tags = list(ascii_tags_loader(f))
    sections, handles, owners, refs, kinds, names = [], {}, {}, [], [], set()
    section = kind = handle = None
    for i, tag in enumerate(tags):
        code, value = tag.code, tag.value
        if code == 0:
            kind, handle = value, None
            if value == "SECTION":
                section = tags[i + 1].value
                sections.append(section)
            elif value not in ("ENDSEC", "ENDTAB", "EOF"):
                kinds.append((section, value))
                nxt = tags[i + 1]
                if value == "TABLE":
                    nxt = tags[i + 2]
                check(nxt.code in (5, 105), f"{path}: {value} in {section} has no handle")
            continue
        if section == "HEADER":
            continue
        if code in (5, 105) and handle is None and kind != "SECTION":
            handle = value
            check(value not in handles, f"{path}: handle {value} twice")
            check(int(value, 16) < seed, f"{path}: handle {value} not below $HANDSEED")
            handles[value] = (section, kind)
        elif code == 330 and handle is not None and handle not in owners:
            owners[handle] = value
        if code in (330, 340, 350) and value != "0":
            refs.append((handle, value))
        if code == 2 and section == "TABLES":
            names.add((kind, value))
    check(sections == ["HEADER", "CLASSES", "TABLES", "BLOCKS", "ENTITIES", "OBJECTS"], f"{path}: sections {sections}")
    for h, (section, kind) in handles.items():
        check(h in owners, f"{path}: {kind} {h} has no owner")
        owner = owners.get(h)
        check(owner in handles or (owner == "0" and kind in ("TABLE", "DICTIONARY")), f"{path}: {kind} {h} owner {owner}")
    for frm, to in refs:
        check(to in handles, f"{path}: {frm} refers to {to}, which is not in the file")
    for table in ("VPORT", "LTYPE", "LAYER", "STYLE", "VIEW", "UCS", "APPID", "DIMSTYLE", "BLOCK_RECORD"):
        check(("TABLE", table) in names, f"{path}: no {table} table")
    for record in (("VPORT", "*Active"), ("LTYPE", "ByBlock"), ("LTYPE", "ByLayer"), ("LTYPE", "Continuous"),
                   ("LAYER", "0"), ("STYLE", "Standard"), ("APPID", "ACAD"), ("DIMSTYLE", "Standard"),
                   ("BLOCK_RECORD", "*Model_Space"), ("BLOCK_RECORD", "*Paper_Space")):
        check(record in names, f"{path}: no {record}")
    check([k for s, k in kinds if s == "BLOCKS"] == ["BLOCK", "ENDBLK", "BLOCK", "ENDBLK"], f"{path}: blocks")
    objects = [k for s, k in kinds if s == "OBJECTS"]
    check(objects.count("LAYOUT") == 2 and objects.count("DICTIONARY") == 3, f"{path}: objects {objects}")
    # ezdxf's view: the root dictionary's ACAD_GROUP and ACAD_LAYOUT, the layouts, the entities'
    # handles and owner (the model space's block record), subclasses as ezdxf parsed them.
    check("ACAD_GROUP" in doc.rootdict and "ACAD_LAYOUT" in doc.rootdict, f"{path}: root dictionary")
    check(sorted(doc.layouts.names()) == ["Layout1", "Model"], f"{path}: layouts {doc.layouts.names()}")
    model = doc.modelspace().block_record_handle
    for e in doc.modelspace():
        check(e.dxf.handle in handles and handles[e.dxf.handle] == ("ENTITIES", e.dxftype()),
              f"{path}: entity {e.dxf.handle}")
        check(e.dxf.owner == model, f"{path}: {e.dxftype()} {e.dxf.handle} owned by {e.dxf.owner}")
        check(doc.layers.has_entry(e.dxf.layer), f"{path}: {e.dxftype()} on a layer {e.dxf.layer!r} not in the table")
    # The extents: the header's box holds every entity's.
    lo, hi = doc.header["$EXTMIN"], doc.header["$EXTMAX"]
    check(lo[0] <= hi[0] and lo[1] <= hi[1], f"{path}: extents {lo} {hi}")
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

check_structure(spline_path)
check_structure(poly_path)
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

# ---------------------------------------------------------------- 2. names and colours as layers
def aci_palette():
    """The AutoCAD Color Index (1–255) as the DXF Reference's colour wheel gives it: 1–9 named, 10–249
    24 hues × 5 values × full and half saturation, 250–255 greys; ACI 7 black or white."""
    pal = {1: (255, 0, 0), 2: (255, 255, 0), 3: (0, 255, 0), 4: (0, 255, 255), 5: (0, 0, 255), 6: (255, 0, 255),
           8: (128, 128, 128), 9: (192, 192, 192)}
    for i in range(10, 250):
        k = i - 10
        value = [255, 165, 127, 76, 38][(k % 10) // 2]
        full = colorsys.hsv_to_rgb((k // 10) * 15 / 360, 1, 1)
        pal[i] = tuple(math.floor(value * (c if k % 2 == 0 else 0.5 + c / 2)) for c in full)
    for i, g in zip(range(250, 256), (51, 80, 105, 130, 190, 255)):
        pal[i] = (g, g, g)
    return pal


def nearest_aci(rgb, pal=aci_palette()):
    dist = lambda c: sum((a - b) ** 2 for a, b in zip(c, rgb))
    best, best_d = 7, min(dist((0, 0, 0)), dist((255, 255, 255)))
    for i in range(1, 256):
        if i != 7 and dist(pal[i]) < best_d:
            best, best_d = i, dist(pal[i])
    return best


with open(DOCUMENT, encoding="utf-8") as f:
    source = json.load(f)
for script, names, page in (
        ("western", ["Front: left/right?", "FRONT: left/right?", "a<b>c\\d\"e;f*g|h=i`j'k", "", "0"], "ANSI_1252"),
        ("latvian", ["Priekša — ķīlis", "Mugura", "Piedurkne"], "ANSI_1257"),
        ("cyrillic", ["Спинка", "Рукав", "Полочка"], "ANSI_1251")):
    named = json.loads(json.dumps(source))
    colours = ["#ff0000", "#0000ff", "#808080", "#ff7f00", "#123456", "#ffffff", "#2a9d8f"]
    for i, curve in enumerate(named["curves"]):
        curve["color"] = colours[i % len(colours)]
        if i < len(names):
            curve["name"] = names[i]
        else:
            curve["name"] = f"{script} {i}"
    doc_path = os.path.join(WORK, f"named-{script}.kontur")
    dxf_path = os.path.join(WORK, f"named-{script}.dxf")
    with open(doc_path, "w", encoding="utf-8") as f:
        json.dump(named, f)
    cli("convert", doc_path, dxf_path)
    doc = check_structure(dxf_path)
    check(doc.header["$DWGCODEPAGE"] == page, f"{script}: code page {doc.header['$DWGCODEPAGE']}")
    entities = list(doc.modelspace())
    layer_names = [e.dxf.layer for e in entities]
    # One layer per name regardless of case (curves read from one layer go back to it), spelled as
    # its first curve names it and coloured by that curve; "0" and "Defpoints" are not taken.
    expected = []
    first = {}
    for curve in named["curves"]:
        base = "".join("_" if c in "<>/\\\":;?*|=`'" or ord(c) < 32 else c for c in curve["name"]).strip()
        if not base:
            expected.append("0")
            continue
        name = f"{base} (2)" if base.lower() in ("0", "defpoints") else base
        expected.append(first.setdefault(name.lower(), (name, curve["color"]))[0])
    check(layer_names == expected, f"{script}: layers {layer_names} vs {expected}")
    for e, curve, layer in zip(entities, named["curves"], expected):
        rgb = tuple(int(curve["color"][k:k + 2], 16) for k in (1, 3, 5))
        check(e.rgb == rgb, f"{script}: {layer!r} true colour {e.rgb} vs {rgb}")
        if layer != "0":
            colour = first[layer.lower()][1]
            layer_rgb = tuple(int(colour[k:k + 2], 16) for k in (1, 3, 5))
            check(doc.layers.get(layer).dxf.color == nearest_aci(layer_rgb),
                  f"{script}: layer {layer!r} ACI {doc.layers.get(layer).dxf.color} vs {nearest_aci(layer_rgb)}")
    check(nearest_aci((255, 0, 0)) == 1 and nearest_aci((0, 0, 0)) == 7 and nearest_aci((128, 128, 128)) == 8,
          "the ACI oracle")
    back = cli("info", dxf_path)["curves"]
    check([c["name"] for c in back] == [n if n != "0" else "" for n in expected], f"{script}: names read back")
print("names and colours: layers in three code pages agree")

# ---------------------------------------------------------------- 3. ezdxf → Kontur
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
