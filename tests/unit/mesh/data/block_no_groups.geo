// The 2 x 1 x 1 block of block.geo (two unit-cube HEX8) without any physical group: gmsh then
// writes every element (points, lines, quadrilaterals, hexahedra) with physical tag 0.
// Generated file: gmsh -3 block_no_groups.geo -format msh22 -o block_no_groups_v22.msh
Point(1) = {0, 0, 0, 1.0};
edge[] = Extrude {2, 0, 0} { Point{1}; Layers{2}; };
face[] = Extrude {0, 1, 0} { Line{edge[1]}; Layers{1}; Recombine; };
body[] = Extrude {0, 0, 1} { Surface{face[1]}; Layers{1}; Recombine; };
