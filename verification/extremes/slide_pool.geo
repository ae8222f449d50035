// verification/extremes: a slide released high on a 45 degree slope runs into a shallow pool.
// x horizontal, y up, gravity along -y; the origin is the slope toe.
//
//  y = 0.70 +-----------------------------------------------------------+ top
//      wall |                      air                                  |
//  y = 0.60 S  P (slide: 0.12 m along the slope, 0.08 m thick)          |
//            \ ##|gate                                                  | end
//             \##Q                                                      |
//              \                                                        |
//  y = 0.06     G---------- water surface (depth 0.06 m) --------------+
//        slope   \  pool                                                |
//  y = 0          T----------------------- bottom ----------------------+
//               x = 0                                                 x = 1.0
//
// The slide's front (the gate foot Q) is 0.59 m along the slope above the shoreline G: it
// drops 0.42 m before it meets the water. The mesh size comes from the scene's cell_size.

slope = 45 * Pi / 180;
dx = Cos(slope);  dy = -Sin(slope);  // along the slope, downhill
nx = Sin(slope);  ny = Cos(slope);   // normal to the slope, out of the bed

depth = 0.06;       // still water depth
top_of_slope = 0.6; // height of the slope top S, at the upstream wall
back = 0.05;        // from S down to the slide's back P, along the slope
length = 0.12;      // slide length along the slope (P to Q)
thick = 0.08;       // slide thickness normal to the slope (the gate's height)
tank = 1.0;         // bottom length from the toe to the end wall
top = 0.7;          // top of the modelled box

sx = -top_of_slope;  sy = top_of_slope;
px = sx + back * dx;  py = sy + back * dy;
qx = px + length * dx;  qy = py + length * dy;

Point(1) = {0, 0, 0};                               // T, toe
Point(2) = {tank, 0, 0};                            // bottom end
Point(3) = {tank, depth, 0};                        // water surface at the end wall
Point(4) = {-depth, depth, 0};                      // G, shoreline
Point(5) = {qx, qy, 0};                             // Q, gate foot
Point(6) = {qx + thick * nx, qy + thick * ny, 0};   // gate top
Point(7) = {px + thick * nx, py + thick * ny, 0};   // slide top, back
Point(8) = {px, py, 0};                             // P, slide back on the slope
Point(9) = {sx, sy, 0};                             // S, slope top
Point(10) = {sx, top, 0};                           // upstream wall top
Point(11) = {tank, top, 0};                         // end wall top

Line(1) = {1, 2};    // bottom
Line(2) = {2, 3};    // end wall beside the water
Line(3) = {3, 4};    // still water surface
Line(4) = {4, 1};    // slope under the water
Line(5) = {5, 6};    // gate
Line(6) = {6, 7};    // slide top
Line(7) = {7, 8};    // slide back
Line(8) = {8, 5};    // slope under the slide
Line(9) = {8, 9};    // slope above the slide
Line(10) = {9, 10};  // upstream wall
Line(11) = {10, 11}; // top
Line(12) = {11, 3};  // end wall above the water
Line(13) = {5, 4};   // slope between the slide and the water

// Counter-clockwise loops: gmsh's triangles come out with positive area.
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};                                // pool
Curve Loop(2) = {5, 6, 7, 8};
Plane Surface(2) = {2};                                // slide
Curve Loop(3) = {-3, -12, -11, -10, -9, -7, -6, -5, 13};
Plane Surface(3) = {3};                                // air

Physical Surface("water") = {1};
Physical Surface("slide") = {2};
Physical Surface("air") = {3};
Physical Curve("slope") = {4, 8, 9, 13};
Physical Curve("bottom") = {1};
Physical Curve("end") = {2, 12};
Physical Curve("wall") = {10};
Physical Curve("top") = {11};
Physical Curve("gate") = {5};
