// Test geometry: the unit square drawn clockwise, so its surface normal points to -z and
// gmsh's triangles come out clockwise. Lituya must reorder them, not reject them.
Point(1) = {0, 0, 0};
Point(2) = {0, 1, 0};
Point(3) = {1, 1, 0};
Point(4) = {1, 0, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("square") = {1};
Physical Curve("left") = {1};
