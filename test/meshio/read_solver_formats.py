#!/usr/bin/env python3
# Reads the .msh, .su2, .inp and .vtu that quad-mesher writes for one .poly with meshio (Debian's
# python3-meshio), an implementation independent of ours, and checks that all four hold the same
# quads and the same boundary markers: those of the .poly's segments; where the mesh has regions,
# the same quads in each region's group.
#
#   read_solver_formats.py QUAD_MESHER INPUT.poly WORK_DIR
#
# Exit status 77 (which ctest takes for "skipped") when meshio is not installed.
import collections
import os
import subprocess
import sys

try:
    import meshio
    import numpy as np
except ImportError:
    print("skipped: python3-meshio (and python3-numpy) are not installed")
    sys.exit(77)


def poly_segment_markers(path):
    """The set of segment markers of a .poly file that has them."""
    rows = []
    with open(path) as f:
        for line in f:
            tokens = line.split("#", 1)[0].split()
            if tokens:
                rows.append(tokens)
    nv = int(rows[0][0])
    header = rows[1 + nv]
    assert len(header) > 1 and header[1] == "1", "the .poly has no segment markers"
    return {int(r[3]) for r in rows[2 + nv:2 + nv + int(header[0])]}


def blocks(mesh, kind):
    return [i for i, b in enumerate(mesh.cells) if b.type == kind]


def count(mesh, kind):
    return sum(len(mesh.cells[i].data) for i in blocks(mesh, kind))


def line_markers(mesh, name):
    """The markers cell-data field `name` gives the line cells, as a set."""
    return {int(v) for i in blocks(mesh, "line") for v in mesh.cell_data[name][i]}


def region_failures(msh, inp, vtu):
    """Where the mesh has regions (the .vtu's field `region`): the same quads of each region
    in the .msh's physical surface groups `region_<tag>` and the .inp's element sets."""
    if "region" not in vtu.cell_data:
        return []
    tags = collections.Counter(int(v) for i in blocks(vtu, "quad") for v in vtu.cell_data["region"][i])
    failures = []
    surfaces = {n for n, (tag, dim) in msh.field_data.items() if dim == 2}
    msh_tags = collections.Counter(int(v) for i in blocks(msh, "quad") for v in msh.cell_data["gmsh:physical"][i])
    if surfaces != {"region_%d" % t for t in tags} or msh_tags != tags:
        failures.append("msh: surface groups %s with %s quads, the .vtu's regions %s" % (sorted(surfaces), msh_tags, tags))
    inp_tags = collections.Counter({int(n[len("region_"):]): sum(len(c) for c in cells)
                                    for n, cells in inp.cell_sets.items() if n.startswith("region_")})
    if inp_tags != tags:
        failures.append("inp: region element sets %s, the .vtu's regions %s" % (inp_tags, tags))
    print("regions", dict(tags))
    return failures


def main():
    cli, poly, work = sys.argv[1:4]
    os.makedirs(work, exist_ok=True)
    out = {ext: os.path.join(work, "naca." + ext) for ext in ("msh", "su2", "inp", "vtu")}
    args = [cli, poly]
    for path in out.values():
        args += ["-o", path]
    subprocess.run(args, check=True)
    markers = poly_segment_markers(poly)
    meshes = {ext: meshio.read(path) for ext, path in out.items()}
    quads = {ext: count(m, "quad") for ext, m in meshes.items()}
    lines = {ext: count(m, "line") for ext, m in meshes.items() if ext != "inp"}
    print("markers", sorted(markers), "quads", quads, "lines", lines)
    failures = []
    if len(set(quads.values())) != 1 or quads["msh"] == 0:
        failures.append("quad counts differ: %s" % quads)
    if len(set(lines.values())) != 1 or lines["msh"] == 0:
        failures.append("boundary line counts differ: %s" % lines)

    msh, su2, inp, vtu = (meshes[e] for e in ("msh", "su2", "inp", "vtu"))
    names = {n for n, (tag, dim) in msh.field_data.items() if dim == 1}
    if names != {"marker_%d" % k for k in markers} or line_markers(msh, "gmsh:physical") != markers:
        failures.append("msh: physical groups %s, line tags %s" % (names, line_markers(msh, "gmsh:physical")))
    if line_markers(su2, "su2:tag") != markers:
        failures.append("su2: marker tags %s" % line_markers(su2, "su2:tag"))
    if set(inp.point_sets) != {"marker_%d" % k for k in markers}:
        failures.append("inp: node sets %s" % sorted(inp.point_sets))
    if sum(len(c) for c in inp.cell_sets.get("domain", [])) != quads["inp"]:
        failures.append("inp: the element set 'domain' is not every quad")
    quad_markers = {int(v) for i in blocks(vtu, "quad") for v in vtu.cell_data["marker"][i]}
    if line_markers(vtu, "marker") != markers or quad_markers != {0}:
        failures.append("vtu: line markers %s, quad markers %s" % (line_markers(vtu, "marker"), quad_markers))
    # each marker's nodes: the .inp's node set, the ends of its .vtu lines
    for k in markers:
        ends = {int(v) for i in blocks(vtu, "line")
                for row, m in zip(vtu.cells[i].data, vtu.cell_data["marker"][i]) if m == k for v in row}
        if ends != {int(v) for v in inp.point_sets.get("marker_%d" % k, [])}:
            failures.append("marker %d: the .inp's node set is not the nodes of the .vtu's lines" % k)
    if not np.array_equal(msh.points[:, :2], vtu.points[:, :2]) or not np.array_equal(su2.points, inp.points):
        failures.append("the formats' points differ")
    failures += region_failures(msh, inp, vtu)
    for f in failures:
        print("FAIL:", f)
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
