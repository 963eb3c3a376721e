// A unit cube of linear tetrahedra (element size 1), its bottom z = 0 a physical surface of triangles.
// gmsh -3 cube_tet.geo -format msh41 -o cube_tet_v41.msh
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Physical Volume("cube") = {1};
Physical Surface("bottom") = {5};
Mesh.CharacteristicLengthMin = 1;
Mesh.CharacteristicLengthMax = 1;
