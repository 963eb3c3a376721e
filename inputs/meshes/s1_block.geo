// Benchmark S1 (docs/benchmarks.md S1, Hird & Russell): elastic block on a rigid base.
// Units m. Block L = 10 (x), width 1 (y), H = 1 (z), x in [0, L], y in [0, 1], z in [0, H],
// meshed with nx x 1 x nz HEX8 by extrusion (default 30 x 1 x 1, CARAT's mesh).
//   gmsh -3 s1_block.geo -format msh41 -o s1_block.msh
//   gmsh -3 s1_block.geo -setnumber nx 60 -setnumber nz 2 -format msh41 -o s1_block_60x1x2.msh
// Physical groups (names used by the deck): volume "block"; surfaces "base" (z = 0, contact
// slave), "top" (z = H, pressure q), "fixed_end" (x = 0), "loaded" (x = L, pressure p),
// "side_y0" (y = 0) and "side_y1" (y = 1) (plane strain: u_y = 0).
If (!Exists(nx))
  nx = 30;
EndIf
If (!Exists(nz))
  nz = 1;
EndIf
L = 10;
H = 1;
Point(1) = {0, 0, 0, 1.0};
edge[] = Extrude {L, 0, 0} { Point{1}; Layers{nx}; };
face[] = Extrude {0, 1, 0} { Line{edge[1]}; Layers{1}; Recombine; };
body[] = Extrude {0, 0, H} { Surface{face[1]}; Layers{nz}; Recombine; };
// body[0]: top, body[1]: volume, body[2..5]: sides swept from the lines of face[1]:
// y = 0, x = L, y = 1, x = 0 (checked on block.geo by the unit tests of the gmsh reader).
Physical Volume("block") = {body[1]};
Physical Surface("base") = {face[1]};
Physical Surface("top") = {body[0]};
Physical Surface("fixed_end") = {body[5]};
Physical Surface("loaded") = {body[3]};
Physical Surface("side_y0") = {body[2]};
Physical Surface("side_y1") = {body[4]};
