"""Writes beam.inp: the cantilever of tests/plane/beam_plane.dck (10 x 1, 20 x 4 CPE4 in the
x-y plane) with MESH BLOCK's node and element numbering (node (i, j) is 1 + i + 21 j, element
(i, j) is 1 + i + 20 j), its node sets beam_xmin, beam_xmax, and the surface beam_ymax (edge S3,
nodes 3-4, of the elements of the row y = 1). Run: python3 make_beam_inp.py > beam.inp"""
NX, NY, LX, LY = 20, 4, 10.0, 1.0


def node(i, j):
    return 1 + i + (NX + 1) * j


print("** The cantilever of tests/plane/beam_plane.dck as CPE4 (written by make_beam_inp.py)")
print("*NODE")
for j in range(NY + 1):
    for i in range(NX + 1):
        print(f"{node(i, j)}, {LX * i / NX!r}, {LY * j / NY!r}")
print("*ELEMENT, TYPE=CPE4, ELSET=beam")
for j in range(NY):
    for i in range(NX):
        print(f"{1 + i + NX * j}, {node(i, j)}, {node(i + 1, j)}, {node(i + 1, j + 1)}, {node(i, j + 1)}")
print("*NSET, NSET=beam_xmin")
print(", ".join(str(node(0, j)) for j in range(NY + 1)))
print("*NSET, NSET=beam_xmax")
print(", ".join(str(node(NX, j)) for j in range(NY + 1)))
print("*ELSET, ELSET=top_row")
print(", ".join(str(1 + i + NX * (NY - 1)) for i in range(NX)))
print("*SURFACE, NAME=beam_ymax")
print("top_row, S3")
