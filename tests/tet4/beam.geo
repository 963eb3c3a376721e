// A 10 x 1 x 1 beam of tetrahedra (order 1: 4 nodes, order 2: 10 nodes): physical volume "beam",
// end faces "xmin", "xmax".
// gmsh -3 -setnumber h <size> [-setnumber order 2] beam.geo -format msh22 -o beam.msh
// (run_cantilever.py: h = 0.5, 0.25, 0.125 for order 1; 0.5, 0.25 for order 2)
SetFactory("OpenCASCADE");
DefineConstant[ h = {0.5, Name "element size"} ];
DefineConstant[ order = {1, Name "element order"} ];
Box(1) = {0, 0, 0, 10, 1, 1};
Physical Volume("beam") = {1};
Physical Surface("xmin") = {1};
Physical Surface("xmax") = {2};
Mesh.CharacteristicLengthMin = h;
Mesh.CharacteristicLengthMax = h;
Mesh.ElementOrder = order;
