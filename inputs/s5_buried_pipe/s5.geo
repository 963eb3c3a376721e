// Benchmark S5: buried pipe under a surface strip load (docs/verification/s5.md).
// Half model (symmetry plane x = 0 through the pipe axis), plane strain slab: the x-z plane
// meshed with structured quadrilaterals (transfinite, recombined) and extruded one layer in y.
// Units m. Soil x in [0, W], z in [-H, 0] (surface z = 0); pipe axis (0, zc); inner radius
// ri = D0/2, wall t, outer radius ro = ri + t; soil cavity radius ro (zero gap). The pipe's
// outer surface and the soil's cavity are distinct entities at the same place (separate nodes):
// the pipe is built and extruded at y = yoff (away from the soil, so that gmsh's automatic
// coherence, which merges the shared faces of the extruded soil blocks, leaves it alone) and
// moved to y = 0 with the coherence switched off (Geometry.AutoCoherence = 0).
// Commands (from inputs/s5_buried_pipe; gmsh 4.8):
//   gmsh s5.geo -3 -format msh22 -setnumber refine 1 -o s5_coarse.msh     (360 HEX8)
//   gmsh s5.geo -3 -format msh22 -setnumber refine 2 -o s5_fine.msh       (1408 HEX8)
//   gmsh s5.geo -3 -format msh22 -setnumber refine 1 -setnumber W 10 -setnumber H 20
//        -setnumber zc -10 -setnumber a 1.5 -setnumber nf 12 -setnumber nb 12 -setnumber nt 12
//        -o s5_block.msh    (closed-form check: the pipe in a 20 D0 block, s5.md)
// Physical groups (names used by the decks):
//   volumes  "soil", "pipe"
//   surfaces "soil_bottom" (z = -H), "soil_far" (x = W), "soil_sym" (x = 0, soil),
//            "pipe_sym" (x = 0, pipe: crown and invert ends of the wall), "front" (y = 0),
//            "back" (y = ty), "load_strip" (z = 0, 0 <= x <= a), "soil_top" (z = 0),
//            "cavity" (soil face of the interface), "pipe_outer", "pipe_inner"
//   points   "crown", "springline", "invert" (pipe outer surface, y = 0; the node sets hold
//            the point's node), and their inner-surface twins "crown_in", "springline_in",
//            "invert_in"
SetFactory("Built-in");
yoff = 100;
If (!Exists(refine)) refine = 1; EndIf
If (!Exists(W))  W = 8;    EndIf   // half width of the soil
If (!Exists(H))  H = 8;    EndIf   // soil height
If (!Exists(zc)) zc = -2;  EndIf   // pipe axis below the surface
If (!Exists(a))  a = 1.0;  EndIf   // half width of the box around the pipe (= loaded strip)
If (!Exists(nc)) nc = 4;   EndIf   // elements per 45 degrees of the pipe (x refine)
If (!Exists(nr)) nr = 6;   EndIf   // radial elements pipe -> box (x refine)
If (!Exists(nt)) nt = 4;   EndIf   // box -> surface (x refine)
If (!Exists(nb)) nb = 8;   EndIf   // box -> bottom (x refine)
If (!Exists(nf)) nf = 10;  EndIf   // box -> far side (x refine)
ri = 0.5; t = 0.002; ro = ri + t; ty = 0.1;
Nc = nc*refine + 1; Nr = nr*refine + 1; Nt = nt*refine + 1; Nb = nb*refine + 1;
Nf = nf*refine + 1;
s2 = Sqrt(2)/2;
// centre, soil cavity points (angle from the crown 0, 45, 90, 135, 180 degrees)
Point(1) = {0, 0, zc};
Point(10) = {0, 0, zc + ro};  Point(11) = {ro*s2, 0, zc + ro*s2};  Point(12) = {ro, 0, zc};
Point(13) = {ro*s2, 0, zc - ro*s2};  Point(14) = {0, 0, zc - ro};
// pipe outer (same places, other entities) and inner points
Point(2) = {0, yoff, zc};
Point(20) = {0, yoff, zc + ro};  Point(21) = {ro*s2, yoff, zc + ro*s2};  Point(22) = {ro, yoff, zc};
Point(23) = {ro*s2, yoff, zc - ro*s2};  Point(24) = {0, yoff, zc - ro};
Point(30) = {0, yoff, zc + ri};  Point(31) = {ri*s2, yoff, zc + ri*s2};  Point(32) = {ri, yoff, zc};
Point(33) = {ri*s2, yoff, zc - ri*s2};  Point(34) = {0, yoff, zc - ri};
// box around the pipe
Point(40) = {0, 0, zc + a};  Point(41) = {a, 0, zc + a};  Point(42) = {a, 0, zc};
Point(43) = {a, 0, zc - a};  Point(44) = {0, 0, zc - a};
// surface, far side, bottom
Point(50) = {0, 0, 0};  Point(51) = {a, 0, 0};  Point(52) = {W, 0, 0};
Point(53) = {W, 0, zc + a};  Point(54) = {W, 0, zc};  Point(55) = {W, 0, zc - a};
Point(56) = {0, 0, -H};  Point(57) = {a, 0, -H};  Point(58) = {W, 0, -H};
// soil cavity arcs 100-103, pipe outer arcs 110-113, pipe inner arcs 120-123
For k In {0:3}
  Circle(100 + k) = {10 + k, 1, 11 + k};
  Circle(110 + k) = {20 + k, 2, 21 + k};
  Circle(120 + k) = {30 + k, 2, 31 + k};
EndFor
// pipe radial lines (one element through the wall) 130-134
For k In {0:4}
  Line(130 + k) = {30 + k, 20 + k};
EndFor
// soil radial lines cavity -> box 140-144, box edges 150-153
For k In {0:4}
  Line(140 + k) = {10 + k, 40 + k};
EndFor
For k In {0:3}
  Line(150 + k) = {40 + k, 41 + k};
EndFor
// outer lines
Line(160) = {50, 51};  Line(161) = {51, 52};                     // surface
Line(162) = {40, 50};  Line(163) = {41, 51};  Line(164) = {53, 52};  // box top -> surface
Line(165) = {41, 53};  Line(166) = {42, 54};  Line(167) = {43, 55};  // box -> far side
Line(168) = {54, 53};  Line(169) = {55, 54};                     // far side upper, lower
Line(170) = {56, 44};  Line(171) = {57, 43};  Line(172) = {58, 55};  // bottom -> box
Line(173) = {56, 57};  Line(174) = {57, 58};                     // bottom
// meshing of the curves
Transfinite Curve{100:103, 110:113, 120:123, 150:153, 160, 168, 169, 173} = Nc;
Transfinite Curve{130:134} = 2;
Transfinite Curve{140:144} = Nr Using Progression 1.25^(1/refine);
Transfinite Curve{162, 163, 164} = Nt;
Transfinite Curve{161, 165, 166, 167, 174} = Nf Using Progression 1.15^(1/refine);
Transfinite Curve{170, 171, 172} = Nb Using Progression 0.9^(1/refine);
// surfaces; every loop runs clockwise in the (x, z) plot (normal +y): extruded along +y the
// hexahedra have positive Jacobians
For k In {0:3}
  Curve Loop(200 + k) = {120 + k, 131 + k, -(110 + k), -(130 + k)};   // pipe wall
  Plane Surface(200 + k) = {200 + k};
  Curve Loop(210 + k) = {100 + k, 141 + k, -(150 + k), -(140 + k)};   // soil ring
  Plane Surface(210 + k) = {210 + k};
EndFor
Curve Loop(220) = {150, 163, -160, -162};     Plane Surface(220) = {220};   // above the box
Curve Loop(221) = {165, 164, -161, -163};     Plane Surface(221) = {221};   // above, right
Curve Loop(222) = {151, 166, 168, -165};      Plane Surface(222) = {222};   // right, upper
Curve Loop(223) = {152, 167, 169, -166};      Plane Surface(223) = {223};   // right, lower
Curve Loop(224) = {-173, 170, -153, -171};    Plane Surface(224) = {224};   // below the box
Curve Loop(225) = {-174, 171, 167, -172};     Plane Surface(225) = {225};   // below, right
Transfinite Surface{200:203, 210:213, 220:225};
Recombine Surface{200:203, 210:213, 220:225};
// extrusion, one layer in y, all surfaces of a body in one command; out[6 i + 0] is the top of the i-th surface, out[6 i + 1] its volume and
// out[6 i + 2 + k] the face swept from the k-th curve of its loop
p[] = Extrude {0, ty, 0} { Surface{200:203}; Layers{1}; Recombine; };
s[] = Extrude {0, ty, 0} { Surface{210:213, 220:225}; Layers{1}; Recombine; };
For k In {0:3}
  pipe_vol[k] = p[6*k + 1]; pipe_back[k] = p[6*k]; pipe_inner[k] = p[6*k + 2];
  pipe_outer[k] = p[6*k + 4];
  soil_vol[k] = s[6*k + 1]; soil_back[k] = s[6*k]; cavity[k] = s[6*k + 2];
EndFor
pipe_sym[0] = p[5]; pipe_sym[1] = p[6*3 + 3];
soil_sym[0] = s[5]; soil_sym[1] = s[6*3 + 3];
For k In {4:9}
  soil_vol[k] = s[6*k + 1]; soil_back[k] = s[6*k];
EndFor
load_strip = s[6*4 + 4]; soil_sym[2] = s[6*4 + 5];
top_right = s[6*5 + 4]; soil_far[0] = s[6*5 + 3];
soil_far[1] = s[6*6 + 4];
soil_far[2] = s[6*7 + 4];
bottom[0] = s[6*8 + 2]; soil_sym[3] = s[6*8 + 3];
bottom[1] = s[6*9 + 2]; soil_far[3] = s[6*9 + 5];
Geometry.AutoCoherence = 0;
Translate {0, -yoff, 0} { Volume{pipe_vol[]}; }
Physical Volume("soil") = {soil_vol[]};
Physical Volume("pipe") = {pipe_vol[]};
Physical Surface("soil_bottom") = {bottom[]};
Physical Surface("soil_far") = {soil_far[]};
Physical Surface("soil_sym") = {soil_sym[]};
Physical Surface("pipe_sym") = {pipe_sym[]};
Physical Surface("front") = {200:203, 210:213, 220:225};
Physical Surface("back") = {pipe_back[], soil_back[]};
Physical Surface("load_strip") = {load_strip};
Physical Surface("soil_top") = {load_strip, top_right};
Physical Surface("cavity") = {cavity[]};
Physical Surface("pipe_outer") = {pipe_outer[]};
Physical Surface("pipe_inner") = {pipe_inner[]};
Physical Point("crown") = {20};
Physical Point("springline") = {22};
Physical Point("invert") = {24};
Physical Point("crown_in") = {30};
Physical Point("springline_in") = {32};
Physical Point("invert_in") = {34};
Physical Point("soil_crown") = {10};
