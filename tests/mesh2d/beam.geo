// The cantilever of tests/plane/beam_plane.dck (10 x 1 in the x-y plane, 20 x 4 quadrilaterals)
// as a gmsh mesh: gmsh -2 beam.geo -format msh41 -o beam.msh
// Physical surface "beam" (the elements), physical curves "beam_xmin" (x = 0), "beam_xmax"
// (x = 10) and "beam_ymax" (y = 1): the names of MESH BLOCK's sets, so that the decks differ
// only in their mesh.
Point(1) = {0, 0, 0};
Point(2) = {10, 0, 0};
Point(3) = {10, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Transfinite Curve {1, 3} = 21;
Transfinite Curve {2, 4} = 5;
Transfinite Surface {1};
Recombine Surface {1};
Physical Surface("beam") = {1};
Physical Curve("beam_xmin") = {4};
Physical Curve("beam_xmax") = {2};
Physical Curve("beam_ymax") = {3};
