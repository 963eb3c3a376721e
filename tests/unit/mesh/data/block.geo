// A 2 x 1 x 1 block, x in [0, 2], y and z in [0, 1], meshed with 2 x 1 x 1 HEX8 (unit cubes)
// by extrusion. Physical groups: volume "block"; surfaces "bottom" (z = 0), "top" (z = 1),
// "left" (x = 0); point "origin" (0, 0, 0); an unnamed curve with tag 7 (the edge y = z = 0),
// which the reader names "1:7".
// Generated files: gmsh -3 block.geo -format msh22 -o block_v22.msh
//                  gmsh -3 block.geo -format msh41 -o block_v41.msh
//                  gmsh -3 block.geo -order 2 -format msh41 -o block_order2_v41.msh
Point(1) = {0, 0, 0, 1.0};
edge[] = Extrude {2, 0, 0} { Point{1}; Layers{2}; };
face[] = Extrude {0, 1, 0} { Line{edge[1]}; Layers{1}; Recombine; };
body[] = Extrude {0, 0, 1} { Surface{face[1]}; Layers{1}; Recombine; };
// body[0]: top surface, body[1]: the volume, body[2..5]: the sides swept from the lines of
// face[1] in their order (y = 0, x = 2, y = 1, x = 0).
Physical Volume("block") = {body[1]};
Physical Surface("bottom") = {face[1]};
Physical Surface("top") = {body[0]};
Physical Surface("left") = {body[5]};
Physical Point("origin") = {1};
Physical Curve(7) = {edge[1]};
