// Case B of Zhao et al. (2023), section 3.2: a dry granular pile slides down a 45 degree
// slope into a water tank (lab: Viroulet et al. 2013, 2014). Real coordinates: x horizontal,
// y up, gravity along -y. The origin is the slope toe, the paper's X = 0 (its X runs the other
// way: X = -x), so the paper's gauges X1 = -0.3 m and X2 = -0.6 m are at x = 0.3 and 0.6,
// i.e. 0.45 m and 0.75 m from the gate, which stands at the still water line x = -h0.
//
//  y = 0.40 +------------------------------------------------------------+  top
//      wall |                         air                                |
//  y = 0.30 +  P  (pile: right triangle, legs 0.144 m along the slope     |
//            \ ###  and 0.144 m normal to it = the gate; its top is        | end
//             \####| gate                                                  |
//  y = 0.15    \###G-----------------water surface (h0 = 0.15 m)----------+
//        slope  \     water                                               |
//  y = 0         T----------------------- bottom -------------------------+
//               x = 0 (toe)                                            x = 1.5
//
// The mesh size comes from the scene's cell_size (lituya pre sets Mesh.MeshSizeMax).

slope = 45 * Pi / 180;
dx = Cos(slope);  dy = -Sin(slope);  // d: along the slope, downhill (towards +x)
nx = Sin(slope);  ny = Cos(slope);   // n: normal to the slope, out of the bed

h0 = 0.15;          // still water depth
leg = 0.144;        // pile: leg along the slope (back to the gate) and gate height
tank = 1.5;         // tank bottom length from the toe to the end wall
top = 0.40;         // top of the modelled box
slope_top = 0.30;   // height where the slope meets the upstream wall

gx = -h0;  gy = h0;  // G: gate foot = still water line on the slope

Point(1) = {0, 0, 0};                                  // T, toe
Point(2) = {tank, 0, 0};                               // bottom end
Point(3) = {tank, h0, 0};                              // water surface at the end wall
Point(4) = {gx, gy, 0};                                // G, gate foot, shoreline
Point(5) = {gx + leg * nx, gy + leg * ny, 0};          // gate top
Point(6) = {gx - leg * dx, gy - leg * dy, 0};          // P, back of the pile on the slope
Point(7) = {-slope_top, slope_top, 0};                 // slope top
Point(8) = {-slope_top, top, 0};                       // upstream wall top
Point(9) = {tank, top, 0};                             // end wall top

Line(1) = {1, 2};    // bottom
Line(2) = {2, 3};    // end wall, beside the water
Line(3) = {3, 4};    // still water surface
Line(4) = {4, 1};    // slope under the water
Line(5) = {4, 5};    // gate
Line(6) = {5, 6};    // pile top (horizontal on a 45 degree slope)
Line(7) = {6, 4};    // slope under the pile
Line(8) = {6, 7};    // slope above the pile
Line(9) = {7, 8};    // upstream wall
Line(10) = {8, 9};   // top
Line(11) = {9, 3};   // end wall, above the water

// Loops run counter-clockwise, so gmsh's triangles come out counter-clockwise (positive).
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};                          // water
Curve Loop(2) = {5, 6, 7};
Plane Surface(2) = {2};                          // pile
Curve Loop(3) = {-3, -11, -10, -9, -8, -6, -5};
Plane Surface(3) = {3};                          // air

Physical Surface("water") = {1};
Physical Surface("pile") = {2};
Physical Surface("air") = {3};
Physical Curve("slope") = {4, 7, 8};
Physical Curve("bottom") = {1};
Physical Curve("end") = {2, 11};
Physical Curve("wall") = {9};
Physical Curve("top") = {10};
Physical Curve("gate") = {5};
