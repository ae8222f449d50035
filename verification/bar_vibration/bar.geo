// 1D elastic bar: a vertical strip, 1 m long and 0.1 m wide, fixed at its base, free at its
// top, between frictionless side walls (rollers). A band of empty mesh above the bar.
L = 1.0;   // bar length
w = 0.1;   // width (two cells: lateral rollers make the problem one-dimensional)
air = 0.1;
Point(1) = {0, 0, 0};
Point(2) = {w, 0, 0};
Point(3) = {w, L, 0};
Point(4) = {0, L, 0};
Point(5) = {w, L + air, 0};
Point(6) = {0, L + air, 0};
Line(1) = {1, 2};  // base
Line(2) = {2, 3};  // right, beside the bar
Line(3) = {3, 4};  // bar top
Line(4) = {4, 1};  // left, beside the bar
Line(5) = {3, 5};  // right, beside the air
Line(6) = {5, 6};  // top of the mesh
Line(7) = {6, 4};  // left, beside the air
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {-3, 5, 6, 7};
Plane Surface(2) = {2};
Physical Surface("bar") = {1};
Physical Surface("air") = {2};
Physical Curve("base") = {1};
Physical Curve("sides") = {2, 4, 5, 7};
Physical Curve("top") = {6};
