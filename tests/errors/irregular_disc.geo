// An unstructured quadrilateral mesh of the disc of radius 2 (its top nodes have 3, 4, 5
// or more faces around them), extruded by one layer of HEX8: the master surface "top" of the
// error case contact_normals_smoothed_valence (NORMALS Smoothed needs at most 4 faces at the
// nodes of each face).
// Generated file: gmsh -3 irregular_disc.geo -format msh22 -o irregular_disc.msh
Mesh.RecombinationAlgorithm = 1;
Mesh.RecombineAll = 1;
Mesh.CharacteristicLengthMax = 0.7;
Point(1) = {0, 0, 0, 0.7};
Point(2) = {2, 0, 0, 0.7};
Point(3) = {0, 2, 0, 0.7};
Point(4) = {-2, 0, 0, 0.7};
Point(5) = {0, -2, 0, 0.7};
Circle(1) = {2, 1, 3};
Circle(2) = {3, 1, 4};
Circle(3) = {4, 1, 5};
Circle(4) = {5, 1, 2};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Recombine Surface{1};
body[] = Extrude {0, 0, 1} { Surface{1}; Layers{1}; Recombine; };
Physical Volume("disc") = {body[1]};
Physical Surface("bottom") = {1};
Physical Surface("top") = {body[0]};
