// The block of block.geo with one volume in two physical volumes, "block" (tag 1) and
// "again" (tag 8). Format 2.2 then writes each hexahedron twice, with different ids
// (gmsh 4.8: 9 and 10 for the first, 11 and 12 for the second); format 4.1 once (9, 10).
// Generated files: gmsh -3 block_two_volumes.geo -format msh22 -o block_two_volumes_v22.msh
//                  gmsh -3 block_two_volumes.geo -format msh41 -o block_two_volumes_v41.msh
Point(1) = {0, 0, 0, 1.0};
edge[] = Extrude {2, 0, 0} { Point{1}; Layers{2}; };
face[] = Extrude {0, 1, 0} { Line{edge[1]}; Layers{1}; Recombine; };
body[] = Extrude {0, 0, 1} { Surface{face[1]}; Layers{1}; Recombine; };
Physical Volume("block") = {body[1]};
Physical Surface("bottom") = {face[1]};
Physical Surface("top") = {body[0]};
Physical Surface("left") = {body[5]};
Physical Point("origin") = {1};
Physical Curve(7) = {edge[1]};
Physical Volume("again") = {body[1]};
