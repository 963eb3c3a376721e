// A plane mesh (x-y plane) for the gmsh reader's 2D tests:
//   gmsh -2 plate2d.geo -format msh22 -o plate2d_v22.msh
//   gmsh -2 plate2d.geo -format msh41 -o plate2d_v41.msh
// x in [0, 2], y in [0, 1]: the square x <= 1 in 2 x 2 quadrilaterals (physical surface
// "quads"), the square x >= 1 in 8 triangles (physical surface "tris"); physical curves
// "bottom" (y = 0, both squares), "right" (x = 2), "left" (x = 0); physical point "origin".
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {2, 0, 0};
Point(4) = {2, 1, 0};
Point(5) = {1, 1, 0};
Point(6) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 5};
Line(5) = {5, 6};
Line(6) = {6, 1};
Line(7) = {2, 5};
Curve Loop(1) = {1, 7, 5, 6};
Plane Surface(1) = {1};
Curve Loop(2) = {2, 3, 4, -7};
Plane Surface(2) = {2};
Transfinite Curve {1, 2, 3, 4, 5, 6, 7} = 3;
Transfinite Surface {1};
Transfinite Surface {2};
Recombine Surface {1};
Physical Surface("quads") = {1};
Physical Surface("tris") = {2};
Physical Curve("bottom") = {1, 2};
Physical Curve("right") = {3};
Physical Curve("left") = {6};
Physical Point("origin") = {1};
