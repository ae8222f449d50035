// A saturated block on a rigid 25 degree incline under still water. Real coordinates (x
// horizontal, y up); the incline descends towards +x from O = (0, 0), the still water line is
// y = 0 (it meets the incline at O). Points are O + s d + t n with d along the slope
// (downhill) and n normal to it.
slope = 25 * Pi / 180;
dx = Cos(slope);  dy = -Sin(slope);
nx = Sin(slope);  ny = Cos(slope);
length = 1.45;              // incline length, to the downstream wall
air = 0.1;                  // empty mesh above the still water line
s0 = 0.25;  s1 = 1.05;  h = 0.06;   // block: s in [s0, s1], t in [0, h]
xe = length * dx;           // the downstream wall, x = xe

Point(1) = {0, 0, 0};
Point(2) = {s0 * dx, s0 * dy, 0};
Point(3) = {s1 * dx, s1 * dy, 0};
Point(4) = {length * dx, length * dy, 0};
Point(5) = {xe, 0, 0};
Point(6) = {xe, air, 0};
Point(7) = {0, air, 0};
Point(8) = {s1 * dx + h * nx, s1 * dy + h * ny, 0};
Point(9) = {s0 * dx + h * nx, s0 * dy + h * ny, 0};

Line(1) = {1, 2};   // bed, upslope of the block
Line(2) = {2, 3};   // bed, under the block
Line(3) = {3, 4};   // bed, downslope
Line(4) = {4, 5};   // downstream wall, below the still water line
Line(5) = {5, 6};   // downstream wall, above it
Line(6) = {6, 7};   // top
Line(7) = {7, 1};   // upstream wall (air only: the water meets the incline at O)
Line(8) = {5, 1};   // still water line
Line(9) = {3, 8};   // block, downslope face
Line(10) = {8, 9};  // block, top
Line(11) = {9, 2};  // block, upslope face

Curve Loop(1) = {2, 9, 10, 11};
Plane Surface(1) = {1};
Curve Loop(2) = {1, -11, -10, -9, 3, 4, 8};
Plane Surface(2) = {2};
Curve Loop(3) = {-8, 5, 6, 7};
Plane Surface(3) = {3};
Physical Surface("block") = {1};
Physical Surface("water") = {2};
Physical Surface("air") = {3};
Physical Curve("bed") = {1, 2, 3};
Physical Curve("walls") = {4, 5, 7};
Physical Curve("top") = {6};
