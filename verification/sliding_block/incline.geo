// A block on a rigid 25 degree incline. Real coordinates (x horizontal, y up); the incline
// descends towards +x from O = (0, 0). Points are O + s d + t n with d along the slope
// (downhill) and n normal to it.
slope = 25 * Pi / 180;
dx = Cos(slope);  dy = -Sin(slope);
nx = Sin(slope);  ny = Cos(slope);
length = 2.0;      // incline length
band = 0.3;        // mesh band above the incline
s0 = 0.2;  s1 = 0.4;  h = 0.1;   // block: s in [s0, s1], t in [0, h]

Point(1) = {0, 0, 0};
Point(2) = {s0 * dx, s0 * dy, 0};
Point(3) = {s1 * dx, s1 * dy, 0};
Point(4) = {length * dx, length * dy, 0};
Point(5) = {length * dx + band * nx, length * dy + band * ny, 0};
Point(6) = {band * nx, band * ny, 0};
Point(7) = {s1 * dx + h * nx, s1 * dy + h * ny, 0};
Point(8) = {s0 * dx + h * nx, s0 * dy + h * ny, 0};

Line(1) = {1, 2};  // bed, upslope of the block
Line(2) = {2, 3};  // bed, under the block
Line(3) = {3, 4};  // bed, downslope
Line(4) = {4, 5};  // lower end
Line(5) = {5, 6};  // top
Line(6) = {6, 1};  // upper end
Line(7) = {3, 7};  // block, downslope face
Line(8) = {7, 8};  // block, top
Line(9) = {8, 2};  // block, upslope face

Curve Loop(1) = {2, 7, 8, 9};
Plane Surface(1) = {1};
Curve Loop(2) = {1, -9, -8, -7, 3, 4, 5, 6};
Plane Surface(2) = {2};
Physical Surface("block") = {1};
Physical Surface("air") = {2};
Physical Curve("bed") = {1, 2, 3};
Physical Curve("ends") = {4, 6};
Physical Curve("top") = {5};
