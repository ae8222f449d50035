// Dam break at a late time: a channel [0, 4.6] x [0, 0.3]; the water column [0, 1.6] x
// [0, 0.2] behind the dam at x = 1.6; "air" is empty mesh the water flows into. "bed" (y = 0)
// and "ends" (x = 0, 4.6). Long enough that at t = 1.0 s neither the rarefaction (back wall
// reached at 1.6 / sqrt(g H) = 1.14 s) nor Ritter's front (2 sqrt(g H) t = 2.8 m past the dam)
// meets a wall.
Point(1) = {0, 0, 0};
Point(2) = {1.6, 0, 0};
Point(3) = {4.6, 0, 0};
Point(4) = {4.6, 0.3, 0};
Point(5) = {1.6, 0.3, 0};
Point(6) = {0, 0.3, 0};
Point(7) = {0, 0.2, 0};
Point(8) = {1.6, 0.2, 0};
Line(1) = {1, 2};
Line(2) = {2, 8};
Line(3) = {8, 7};
Line(4) = {7, 1};
Line(5) = {2, 3};
Line(6) = {3, 4};
Line(7) = {4, 5};
Line(8) = {5, 6};
Line(9) = {6, 7};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, 8, 9, -3, -2};
Plane Surface(2) = {2};
Physical Surface("water") = {1};
Physical Surface("air") = {2};
Physical Curve("bed") = {1, 5};
Physical Curve("ends") = {4, 9, 6};
