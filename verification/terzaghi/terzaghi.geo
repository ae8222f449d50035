// Terzaghi column: soil [0, 0.1] x [0, 1]; "air" [0, 0.1] x [1, 1.1] above it takes the
// expelled water. "base" (y = 0), "sides" (x = 0 and x = 0.1), "top" (the soil surface).
Point(1) = {0, 0, 0};
Point(2) = {0.1, 0, 0};
Point(3) = {0.1, 1.0, 0};
Point(4) = {0, 1.0, 0};
Point(5) = {0.1, 1.1, 0};
Point(6) = {0, 1.1, 0};
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
Physical Surface("soil") = {1};
Physical Surface("air") = {2};
Physical Curve("base") = {1};
Physical Curve("sides") = {2, 4, 5, 7};
Physical Curve("top") = {3};
