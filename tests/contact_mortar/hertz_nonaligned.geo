// Hertz with NON-aligned meshes for mortar contact (tests/contact_mortar/mortar.cmake): the V6
// geometry of inputs/v6_hertz/v6_hertz.geo, the cylinder meshed with h near the contact point
// and the block with hb = 0.62 h, so that hardly any slave node lies above a master node.
// Make the mesh:  gmsh -3 hertz_nonaligned.geo -format msh22 -o hertz_nonaligned.msh
// The original's notes:
// V6 Hertz: half cylinder (quarter disk extruded) on a flat block, plane-strain slab.
// Half model (x >= 0, symmetry plane x = 0), one element through y (thickness T).
// Cylinder: radius R, centre (0, 0, R), touching the block at the origin; block [0, W] x [0, T]
// x [-H, 0]. Element size h near the contact point (DistMin around it), growing to hmax.
// Make the mesh:  gmsh -3 v6_hertz.geo -format msh22 -o v6_hertz.msh        (h = 0.008)
//                 gmsh -3 v6_hertz.geo -setnumber h 0.004 -format msh22 -o v6_hertz_fine.msh
// OpenCASCADE kernel without BooleanFragments: the cylinder and the block are independent
// volumes with DIFFERENT points at the origin, so the two bodies share no node (they interact
// through contact only). (The built-in kernel merges the two points; with its AutoCoherence
// off, the extrusion duplicates nodes instead.)
SetFactory("OpenCASCADE");
If (!Exists(h))
  h = 0.008;
EndIf
hb = 0.62*h;
R = 1.0; W = 2.0; H = 2.0; T = 0.01;
hmax = 0.15;
// cylinder (x-z plane at y = 0)
p1 = newp; Point(p1) = {0, 0, 0, h};
p2 = newp; Point(p2) = {0, 0, R, hmax};      // centre
p3 = newp; Point(p3) = {R, 0, R, hmax};
c1 = newl; Circle(c1) = {p1, p2, p3};        // contact arc
c2 = newl; Line(c2) = {p3, p2};              // top z = R (loaded)
c3 = newl; Line(c3) = {p2, p1};              // symmetry x = 0
cl1 = newll; Curve Loop(cl1) = {c1, c2, c3};
s1 = news; Plane Surface(s1) = {cl1};
// block
q1 = newp; Point(q1) = {0, 0, 0, h};
q2 = newp; Point(q2) = {W, 0, 0, hmax};
q3 = newp; Point(q3) = {W, 0, -H, hmax};
q4 = newp; Point(q4) = {0, 0, -H, hmax};
d1 = newl; Line(d1) = {q1, q2};              // top z = 0 (contact)
d2 = newl; Line(d2) = {q2, q3};              // x = W
d3 = newl; Line(d3) = {q3, q4};              // bottom
d4 = newl; Line(d4) = {q4, q1};              // symmetry x = 0
cl2 = newll; Curve Loop(cl2) = {d1, d2, d3, d4};
s2 = news; Plane Surface(s2) = {cl2};
// size field: h within 0.15 of the contact point, growing to hmax at distance 1
// (here one per body: h on the cylinder, hb on the block)
Field[1] = Distance; Field[1].PointsList = {p1, q1};
Field[2] = Threshold; Field[2].InField = 1; Field[2].SizeMin = h; Field[2].SizeMax = hmax;
Field[2].DistMin = 0.15; Field[2].DistMax = 1.0;
Field[3] = Restrict; Field[3].InField = 2; Field[3].SurfacesList = {s1}; Field[3].CurvesList = {c1, c2, c3};
Field[4] = Threshold; Field[4].InField = 1; Field[4].SizeMin = hb; Field[4].SizeMax = hmax;
Field[4].DistMin = 0.15; Field[4].DistMax = 1.0;
Field[5] = Restrict; Field[5].InField = 4; Field[5].SurfacesList = {s2}; Field[5].CurvesList = {d1, d2, d3, d4};
Field[6] = Min; Field[6].FieldsList = {3, 5};
Background Field = 6;
Mesh.MeshSizeExtendFromBoundary = 0;
Mesh.MeshSizeFromPoints = 0;
Mesh.RecombineAll = 1;
Mesh.Algorithm = 6;                     // Frontal-Delaunay (8 segfaults in gmsh 4.8.4 here)
Mesh.RecombinationAlgorithm = 1;
Recombine Surface{s1, s2};
// one layer of hexahedra through y
e1[] = Extrude {0, T, 0} { Surface{s1}; Layers{1}; Recombine; };
e2[] = Extrude {0, T, 0} { Surface{s2}; Layers{1}; Recombine; };
// e1: [0] back surface, [1] volume, [2..4] lateral surfaces from c1, c2, c3
Physical Volume("cylinder") = {e1[1]};
Physical Volume("block") = {e2[1]};
Physical Surface("cyl_arc") = {e1[2]};
Physical Surface("cyl_top") = {e1[3]};
Physical Surface("cyl_sym") = {e1[4]};
Physical Surface("block_top") = {e2[2]};
Physical Surface("block_right") = {e2[3]};
Physical Surface("block_bottom") = {e2[4]};
Physical Surface("block_sym") = {e2[5]};
