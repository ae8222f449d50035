// Test geometry: a 2D tank, the rectangle [0, 1] x [0, 0.7]. Water fills [0, 1] x [0, 0.5]
// ("water"); "air" above it is empty background. Curves: "bottom" (y = 0), "sides" (x = 0 and
// x = 1, both surfaces).
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 0.5, 0};
Point(4) = {0, 0.5, 0};
Point(5) = {1, 0.7, 0};
Point(6) = {0, 0.7, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Line(5) = {3, 5};
Line(6) = {5, 6};
Line(7) = {6, 4};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7};
Plane Surface(2) = {2};
Physical Surface("water") = {1};
Physical Surface("air") = {2};
Physical Curve("bottom") = {1};
Physical Curve("sides") = {2, 4, 5, 7};
