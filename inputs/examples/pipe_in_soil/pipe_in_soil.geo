// A steel pipe in a cavity of a soil block, for frix (docs/tutorial-pipe-in-soil.md).
// Units: m. The pipe's axis is y (0 <= y <= L); x is sideways, z up.
// Soil: the box [-a, a] x [0, L] x [-a, a] with a cylindrical cavity of radius ro.
// Pipe: outer radius ro, inner radius ri, in the cavity. The pipe's outer surface and the
// cavity's surface lie on each other but have their own nodes (the contact pair's two sides).
//
//   gmsh -3 pipe_in_soil.geo -format msh22 -o pipe_in_soil.msh

// gmsh's built-in kernel merges points, curves and surfaces at the same place whenever it
// extrudes or moves entities (Geometry.AutoCoherence = 1, the default). That joins the four
// extruded quarters of each body, as it should, but it would also join the pipe to the
// soil on the cavity. So the pipe is built off to the side (x shifted by `away`), both
// bodies are extruded, and only then, with the merging switched off, the pipe is moved
// into the cavity: the two surfaces lie on each other with their own points and nodes.

a = 2.0;     // half-width of the soil block
L = 4.0;     // length along the pipe
ro = 0.5;    // outer radius of the pipe = radius of the cavity
ri = 0.4;    // inner radius of the pipe
n_arc = 5;   // points on each quarter arc (and each quarter of the block's sides)
n_soil = 6;  // points from the cavity out to the block's sides
n_wall = 3;  // points through the pipe's wall
n_axis = 8;  // element layers along the pipe
away = 10;   // the pipe is built at x + away, then moved into the cavity
s = Sqrt(0.5);

// ---- soil cross-section at y = 0: four quadrilaterals between the cavity and the square
Point(1) = {0, 0, 0};
Point(2) = { ro*s, 0,  ro*s}; Point(3) = {-ro*s, 0,  ro*s};
Point(4) = {-ro*s, 0, -ro*s}; Point(5) = { ro*s, 0, -ro*s};
Point(6) = { a, 0,  a}; Point(7) = {-a, 0,  a};
Point(8) = {-a, 0, -a}; Point(9) = { a, 0, -a};
Circle(1) = {2, 1, 3}; Circle(2) = {3, 1, 4}; Circle(3) = {4, 1, 5}; Circle(4) = {5, 1, 2};
Line(5) = {6, 7}; Line(6) = {7, 8}; Line(7) = {8, 9}; Line(8) = {9, 6};
Line(9) = {2, 6}; Line(10) = {3, 7}; Line(11) = {4, 8}; Line(12) = {5, 9};
Curve Loop(1) = {9, 5, -10, -1};  Plane Surface(1) = {1};   // top
Curve Loop(2) = {10, 6, -11, -2}; Plane Surface(2) = {2};   // -x side
Curve Loop(3) = {11, 7, -12, -3}; Plane Surface(3) = {3};   // bottom
Curve Loop(4) = {12, 8, -9, -4};  Plane Surface(4) = {4};   // +x side

// ---- pipe cross-section at y = 0, built at x + away: a ring of four quadrilaterals
Point(101) = {away, 0, 0};
Point(102) = {away + ro*s, 0,  ro*s}; Point(103) = {away - ro*s, 0,  ro*s};
Point(104) = {away - ro*s, 0, -ro*s}; Point(105) = {away + ro*s, 0, -ro*s};
Point(106) = {away + ri*s, 0,  ri*s}; Point(107) = {away - ri*s, 0,  ri*s};
Point(108) = {away - ri*s, 0, -ri*s}; Point(109) = {away + ri*s, 0, -ri*s};
Circle(101) = {102, 101, 103}; Circle(102) = {103, 101, 104};
Circle(103) = {104, 101, 105}; Circle(104) = {105, 101, 102};
Circle(105) = {106, 101, 107}; Circle(106) = {107, 101, 108};
Circle(107) = {108, 101, 109}; Circle(108) = {109, 101, 106};
Line(109) = {106, 102}; Line(110) = {107, 103}; Line(111) = {108, 104}; Line(112) = {109, 105};
Curve Loop(101) = {109, 101, -110, -105}; Plane Surface(101) = {101};
Curve Loop(102) = {110, 102, -111, -106}; Plane Surface(102) = {102};
Curve Loop(103) = {111, 103, -112, -107}; Plane Surface(103) = {103};
Curve Loop(104) = {112, 104, -109, -108}; Plane Surface(104) = {104};

// ---- structured quadrilaterals: transfinite curves and surfaces, recombined
Transfinite Curve{1:8, 101:108} = n_arc;
Transfinite Curve{9:12} = n_soil Using Progression 1.25;   // finer near the cavity
Transfinite Curve{109:112} = n_wall;
Transfinite Surface{1:4, 101:104};
Recombine Surface{1:4, 101:104};

// ---- hexahedra: the cross-sections extruded along y in layers
soil[] = Extrude {0, L, 0} { Surface{1:4}; Layers{n_axis}; Recombine; };
pipe[] = Extrude {0, L, 0} { Surface{101:104}; Layers{n_axis}; Recombine; };
Geometry.AutoCoherence = 0;
Translate {-away, 0, 0} { Volume{pipe[1], pipe[7], pipe[13], pipe[19]}; }
// Extrude returns, per surface: [0] the far copy (y = L), [1] the volume, [2..5] the sides
// extruded from the curve loop's curves in order.
// soil surface k (loop {outer line, square side, -line, -arc}): side [5] is the cavity,
// [3] the block's side; pipe surface k (loop {line, outer arc, -line, -inner arc}): [3] the
// outer surface, [5] the inner one.

Physical Volume("soil") = {soil[1], soil[7], soil[13], soil[19]};
Physical Volume("pipe") = {pipe[1], pipe[7], pipe[13], pipe[19]};
Physical Surface("cavity") = {soil[5], soil[11], soil[17], soil[23]};
Physical Surface("pipe_outer") = {pipe[3], pipe[9], pipe[15], pipe[21]};
Physical Surface("soil_top") = {soil[3]};
Physical Surface("soil_bottom") = {soil[15]};
Physical Surface("soil_sides") = {soil[9], soil[21]};
Physical Surface("soil_ends") = {1:4, soil[0], soil[6], soil[12], soil[18]};
Physical Surface("pipe_end0") = {101:104};
Physical Surface("pipe_end1") = {pipe[0], pipe[6], pipe[12], pipe[18]};
