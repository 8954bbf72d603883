#!/usr/bin/python3
"""An ASTM D6673 (AAMA) DXF as ezdxf (Debian's python3-ezdxf) reads it, layer by layer, for the window
tests: each block's entities by layer and type, the texts on layer 1, and the POINTs on layers 4 and 13
(notches and drill holes) with their positions in the block. Prints one JSON object:
{"layers": {"1": {"POLYLINE": 1, "TEXT": 3}, ...}, "texts": [...], "points": {"4": [[x, y, angle]], ...}}

Usage: aama_layers.py FILE. Exits 77 (skipped) when ezdxf is not installed.
"""
import json
import sys

try:
    import ezdxf
except ImportError:
    print("SKIP: python3-ezdxf is not installed (packaging/bootstrap installs it)")
    sys.exit(77)


def main():
    doc = ezdxf.readfile(sys.argv[1])
    layers, texts, points = {}, [], {}
    for block in doc.blocks:
        if block.name.startswith("*"):
            continue
        for e in block:
            kind = e.dxftype()
            layer = e.dxf.layer
            layers.setdefault(layer, {}).setdefault(kind, 0)
            layers[layer][kind] += 1
            if kind == "TEXT" and layer == "1":
                texts.append(e.dxf.text)
            if kind == "POINT":
                loc = e.dxf.location
                points.setdefault(layer, []).append([loc.x, loc.y, e.dxf.get("angle", 0.0)])
    print(json.dumps({"layers": layers, "texts": texts, "points": points}))


if __name__ == "__main__":
    main()
