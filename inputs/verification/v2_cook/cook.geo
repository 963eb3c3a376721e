// Cook's membrane (Cook 1974; e.g. Simo & Rifai 1990, Fig. 9): the trapezoid
// (0,0)-(48,44)-(48,60)-(0,44) in the x-y plane, thickness 1 in z, N x N quadrilaterals
// (transfinite, uniform on every edge) extruded into one layer of HEX8.
// Mesh: gmsh -3 cook.geo -setnumber N 4 -format msh22 -o cook_4x4.msh
// Node ids: gmsh numbers the nodes of the geometric points first, so points 1-8 are nodes
// 1-8: node 3 = (48, 60, 0) is the tip (top right corner), node 7 = (48, 60, 1).
If (!Exists(N))
  N = 4;
EndIf
Point(1) = {0, 0, 0};
Point(2) = {48, 44, 0};
Point(3) = {48, 60, 0};
Point(4) = {0, 44, 0};
Point(5) = {0, 0, 1};
Point(6) = {48, 44, 1};
Point(7) = {48, 60, 1};
Point(8) = {0, 44, 1};
Line(1) = {1, 2}; Line(2) = {2, 3}; Line(3) = {3, 4}; Line(4) = {4, 1};
Line(5) = {5, 6}; Line(6) = {6, 7}; Line(7) = {7, 8}; Line(8) = {8, 5};
Line(9) = {1, 5}; Line(10) = {2, 6}; Line(11) = {3, 7}; Line(12) = {4, 8};
Curve Loop(1) = {1, 2, 3, 4};    Plane Surface(1) = {1};     // z = 0
Curve Loop(2) = {5, 6, 7, 8};    Plane Surface(2) = {2};     // z = 1
Curve Loop(3) = {1, 10, -5, -9}; Plane Surface(3) = {3};     // bottom edge face
Curve Loop(4) = {2, 11, -6, -10}; Plane Surface(4) = {4};    // x = 48 (loaded)
Curve Loop(5) = {3, 12, -7, -11}; Plane Surface(5) = {5};    // top edge face
Curve Loop(6) = {4, 9, -8, -12}; Plane Surface(6) = {6};     // x = 0 (clamped)
Surface Loop(1) = {1, 2, 3, 4, 5, 6};
Volume(1) = {1};
Transfinite Curve {1, 2, 3, 4, 5, 6, 7, 8} = N + 1;
Transfinite Curve {9, 10, 11, 12} = 2;
Transfinite Surface {1, 2, 3, 4, 5, 6};
Recombine Surface {1, 2, 3, 4, 5, 6};
Transfinite Volume {1};
Physical Volume("membrane") = {1};
Physical Surface("clamped") = {6};
Physical Surface("loaded") = {4};
Mesh.ElementOrder = 1;
