#!/usr/bin/python3
"""DXF patterns checked by another program's reader and writer (ezdxf, Debian's python3-ezdxf).

  dxf_ezdxf.py check EXPORT.dxf GARMENT.json
      ezdxf audits Mannequin's export with no error; per panel a block with a
      closed boundary on layer 1 and a sew line on layer 14 whose area, as
      ezdxf flattens it, is the panel's area in GARMENT.json
      (mannequin-cli garment --json) within 0.5 %.
  dxf_ezdxf.py write-foreign OUT.dxf
      writes a pattern as a pattern CAD program would: centimetres, a block per
      piece with a closed polyline (a curved side as a bulge) on layer 1 and a
      "Piece Name:" text, and no Mannequin layers. Prints the pieces' areas in
      cm2 as JSON.
"""
import json
import sys

import ezdxf
from ezdxf import recover
from ezdxf.math import area as polygon_area


def fail(message):
    print("FAIL: " + message)
    sys.exit(1)


def check(dxf_path, garment_path):
    doc, auditor = recover.readfile(dxf_path)
    if auditor.has_errors:
        fail("ezdxf audit errors: " + "; ".join(e.message for e in auditor.errors))
    if doc.header.get("$INSUNITS") != 4:
        fail("$INSUNITS is not 4 (millimetres)")
    garment = json.load(open(garment_path))["garments"][0]
    inserted = [e.dxf.name for e in doc.modelspace().query("INSERT")]
    if len(inserted) != len(garment["panels"]):
        fail(f"{len(inserted)} inserted blocks for {len(garment['panels'])} panels")
    for block_name, panel in zip(inserted, garment["panels"]):
        block = doc.blocks.get(block_name)
        boundaries = [e for e in block.query("LWPOLYLINE") if e.dxf.layer == "1" and e.closed]
        if len(boundaries) != 1:
            fail(f"{block_name}: {len(boundaries)} closed boundaries on layer 1")
        sew = [e for e in block if e.dxf.layer == "14"]
        if len(sew) != panel["edges"]:
            fail(f"{block_name}: {len(sew)} sew-line entities for {panel['edges']} edges")
        points = []
        for entity in sew:  # in order, each from its edge's start corner
            if entity.dxftype() == "LINE":
                points.append(entity.dxf.start)
            else:
                points.extend(list(entity.flattening(0.01))[:-1])
        area_cm2 = abs(polygon_area(points)) / 100.0
        if abs(area_cm2 - panel["area_cm2"]) > 0.005 * panel["area_cm2"]:
            fail(f"{block_name}: sew line encloses {area_cm2:.1f} cm2, the panel is {panel['area_cm2']:.1f} cm2")
        print(f"{block_name}: {len(sew)} edges, {area_cm2:.1f} cm2 (panel {panel['area_cm2']:.1f} cm2)")
    print("ok")


def write_foreign(out_path):
    doc = ezdxf.new("R2000", units=5)  # centimetres
    for layer in ("1", "2", "7"):
        doc.layers.add(layer)
    # A 40 x 60 cm rectangle, and a 30 x 20 cm panel whose top is a half circle (bulge 1).
    pieces = {
        "BODY": ([(0, 0, 0), (40, 0, 0), (40, 60, 0), (0, 60, 0)], 40 * 60),
        "POCKET": ([(0, 0, 0), (30, 0, 0), (30, 20, 1), (0, 20, 0)], 30 * 20 + 3.141592653589793 * 15 * 15 / 2),
    }
    msp = doc.modelspace()
    x = 0
    for name, (points, _) in pieces.items():
        block = doc.blocks.new(name=name)
        block.add_lwpolyline(points, format="xyb", close=True, dxfattribs={"layer": "1"})
        for p in points:
            block.add_point((p[0], p[1]), dxfattribs={"layer": "2"})
        block.add_text("Piece Name: " + name.lower(), dxfattribs={"layer": "1", "height": 1.5, "insert": (5, 5)})
        msp.add_blockref(name, (x, 0))
        x += 50
    doc.saveas(out_path)
    print(json.dumps({name.lower(): area for name, (_, area) in pieces.items()}))


if __name__ == "__main__":
    if len(sys.argv) == 4 and sys.argv[1] == "check":
        check(sys.argv[2], sys.argv[3])
    elif len(sys.argv) == 3 and sys.argv[1] == "write-foreign":
        write_foreign(sys.argv[2])
    else:
        fail(__doc__)
