// Case C of Zhao et al. (2023), section 3.3: a dry or saturated granular deposit slides down a
// 22 degree slope covered by a rigid (linear elastic) or erodible (Mohr-Coulomb) layer into a
// water tank. One geometry for the four scenes; they differ only in materials.
//
// Real coordinates: x horizontal, y up, gravity along -y. The origin is the toe of the slope
// surface, taken as the paper's gauge position X = 0 (see README.md); x runs into the tank.
// The slope surface S descends towards +x; the layer lies under S, `layer` thick normal to it,
// on the rigid bed B (the mesh boundary). The gate stands normal to the slope at the still
// water line and cuts through the layer down to the bed.
//
//  y = 0.45 +---------------------------------------------------------------+  top
//      wall |                             air                               |
//           A_S__P (deposit: 0.38 m along S, 0.144 m normal to S = gate)    |
//           |  layer\#######|GT                                             | end
//  y = 0.15 A_B    dry\#####G---------- water surface -----------------------+
//             \_       \___ | gate through the layer to B (Gb)               |
//               \_  layer    \___        water                               |
//  y = 0          \_  wet         \___T----------- bottom (2.9 m) -----------+
//                   \______________Tb  toe face                            x = 2.9
//
// The mesh size comes from the scene's cell_size (lituya pre sets Mesh.MeshSizeMax).

slope = 22 * Pi / 180;
dx = Cos(slope);  dy = -Sin(slope);  // d: along the slope, downhill (towards +x)
nx = Sin(slope);  ny = Cos(slope);   // n: normal to the slope, out of the bed

h0 = 0.15;          // still water surface above the tank bottom
along = 0.38;       // deposit: leg along the slope
height = 0.144;     // deposit: leg normal to the slope (the gate)
layer = 0.04;       // rigid / erodible layer thickness, normal to the slope (our choice)
tank = 2.9;         // tank bottom length, toe to end wall (the paper's Table 1)
xw = -0.80;         // upstream wall, a little above the deposit's back corner
top = 0.45;         // top of the modelled box

gx = -h0 / Tan(slope);  gy = h0;   // G: gate foot = still water line on S
ox = -layer * nx;  oy = -layer * ny;  // offset from S to B

Point(1) = {0, 0, 0};                                    // T, toe of S
Point(2) = {tank, 0, 0};                                 // bottom end
Point(3) = {tank, h0, 0};                                // water surface at the end wall
Point(4) = {gx, gy, 0};                                  // G, gate foot, shoreline
Point(5) = {gx + height * nx, gy + height * ny, 0};      // gate top
Point(6) = {gx - along * dx, gy - along * dy, 0};        // P, back of the deposit on S
Point(7) = {xw, -xw * Tan(slope), 0};                    // A_S, S at the upstream wall
Point(8) = {xw, top, 0};                                 // upstream wall top
Point(9) = {tank, top, 0};                               // end wall top
Point(10) = {xw, -xw * Tan(slope) - layer / Cos(slope), 0};  // A_B, B at the upstream wall
Point(11) = {gx + ox, gy + oy, 0};                       // Gb, gate foot on B
Point(12) = {0, -layer / Cos(slope), 0};                 // Tb, B below the toe

Line(1) = {1, 2};     // tank bottom
Line(2) = {2, 3};     // end wall, beside the water
Line(3) = {3, 4};     // still water surface
Line(4) = {4, 1};     // S under the water (top of the wet layer)
Line(5) = {4, 5};     // gate beside the deposit
Line(6) = {5, 6};     // deposit top
Line(7) = {6, 4};     // S under the deposit
Line(8) = {6, 7};     // S above the deposit
Line(9) = {7, 8};     // upstream wall beside the air
Line(10) = {8, 9};    // top
Line(11) = {9, 3};    // end wall, above the water
Line(12) = {10, 7};   // upstream wall beside the layer
Line(13) = {10, 11};  // B under the dry layer
Line(14) = {11, 4};   // gate through the layer
Line(15) = {11, 12};  // B under the wet layer
Line(16) = {12, 1};   // toe face of the layer

// Loops run counter-clockwise, so gmsh's triangles come out counter-clockwise (positive).
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};                           // water
Curve Loop(2) = {5, 6, 7};
Plane Surface(2) = {2};                           // deposit
Curve Loop(3) = {-3, -11, -10, -9, -8, -6, -5};
Plane Surface(3) = {3};                           // air
Curve Loop(4) = {13, 14, -7, 8, -12};
Plane Surface(4) = {4};                           // layer above the still water line (dry)
Curve Loop(5) = {15, 16, -4, -14};
Plane Surface(5) = {5};                           // layer below it (saturated)

Physical Surface("water") = {1};
Physical Surface("slide") = {2};
Physical Surface("air") = {3};
Physical Surface("layer_dry") = {4};
Physical Surface("layer_wet") = {5};
Physical Curve("bed") = {12, 13, 15, 16};
Physical Curve("bottom") = {1};
Physical Curve("end") = {2, 11};
Physical Curve("wall") = {9};
Physical Curve("top") = {10};
Physical Curve("gate") = {5, 14};
