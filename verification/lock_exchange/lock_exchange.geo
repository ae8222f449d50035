// Lock exchange (verification/lock_exchange/README.md): a channel 1.2 m long whose water stands
// 0.2 m deep. Behind a gate at x = 0.2 m the lock holds a saturated soil [0, 0.2] x [0, 0.2]
// instead of water; empty mesh ("air") above the water to y = 0.3 m. "bed" (y = 0), "ends"
// (x = 0 and x = 1.2), "top" (y = 0.3) and "gate" (x = 0.2, the lock's face).
Point(1) = {0, 0, 0};
Point(2) = {0.2, 0, 0};
Point(3) = {1.2, 0, 0};
Point(4) = {1.2, 0.2, 0};
Point(5) = {0.2, 0.2, 0};
Point(6) = {0, 0.2, 0};
Point(7) = {1.2, 0.3, 0};
Point(8) = {0, 0.3, 0};
Line(1) = {1, 2};
Line(2) = {2, 5};
Line(3) = {5, 6};
Line(4) = {6, 1};
Line(5) = {2, 3};
Line(6) = {3, 4};
Line(7) = {4, 5};
Line(8) = {4, 7};
Line(9) = {7, 8};
Line(10) = {8, 6};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -2};
Plane Surface(2) = {2};
Curve Loop(3) = {-7, 8, 9, 10, -3};
Plane Surface(3) = {3};
Physical Surface("soil") = {1};
Physical Surface("water") = {2};
Physical Surface("air") = {3};
Physical Curve("bed") = {1, 5};
Physical Curve("ends") = {4, 10, 6, 8};
Physical Curve("top") = {9};
Physical Curve("gate") = {2};
