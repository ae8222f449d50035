// verification/extremes: a block of soil resting on a 60 degree slope, no gate, nothing holding
// it but its own strength and the rough (fixed) slope. The slope runs from S (x = 0, y = 0.6)
// down to its toe T (x = 0.6 tan 30 deg, y = 0); the block is 0.2 m along the slope and
// H = 0.1 m thick, its back 0.2 m below S. "air" is empty mesh around it.
slope = 60 * Pi / 180;
dx = Cos(slope);  dy = -Sin(slope);
nx = Sin(slope);  ny = Cos(slope);
height = 0.6;
back = 0.2;
length = 0.2;
thick = 0.1;
toe = height / Tan(slope);
px = back * dx;  py = height + back * dy;
qx = px + length * dx;  qy = py + length * dy;
right = toe + 0.2;

Point(1) = {0, height, 0};                          // S, slope top
Point(2) = {px, py, 0};                             // block back on the slope
Point(3) = {qx, qy, 0};                             // block front on the slope
Point(4) = {toe, 0, 0};                             // T, toe
Point(5) = {right, 0, 0};                           // bottom end
Point(6) = {right, height + 0.1, 0};                // box corner
Point(7) = {0, height + 0.1, 0};                    // upstream wall top
Point(8) = {qx + thick * nx, qy + thick * ny, 0};   // block front top
Point(9) = {px + thick * nx, py + thick * ny, 0};   // block back top

Line(1) = {1, 2};   // slope above the block
Line(2) = {2, 3};   // slope under the block
Line(3) = {3, 4};   // slope below the block
Line(4) = {4, 5};   // bottom
Line(5) = {5, 6};   // end wall
Line(6) = {6, 7};   // top
Line(7) = {7, 1};   // upstream wall
Line(8) = {3, 8};   // block front
Line(9) = {8, 9};   // block top
Line(10) = {9, 2};  // block back

Curve Loop(1) = {2, 8, 9, 10};
Plane Surface(1) = {1};                      // block
Curve Loop(2) = {1, -10, -9, -8, 3, 4, 5, 6, 7};
Plane Surface(2) = {2};                      // air

Physical Surface("block") = {1};
Physical Surface("air") = {2};
Physical Curve("slope") = {1, 2, 3};
Physical Curve("box") = {4, 5, 6, 7};
