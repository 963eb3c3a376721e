// A 10 x 1 x 1 beam of linear tetrahedra: physical volume "beam", end faces "xmin", "xmax".
// gmsh -3 -setnumber h <size> beam.geo -format msh22 -o beam.msh (run_cantilever.py: h = 0.5, 0.25, 0.125)
SetFactory("OpenCASCADE");
DefineConstant[ h = {0.5, Name "element size"} ];
Box(1) = {0, 0, 0, 10, 1, 1};
Physical Volume("beam") = {1};
Physical Surface("xmin") = {1};
Physical Surface("xmax") = {2};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
Mesh.ElementOrder = 1;
