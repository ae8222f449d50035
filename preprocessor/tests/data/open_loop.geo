// Test geometry: the unit square whose curve loop misses its last side, so the loop is
// open. gmsh reads it and fails only while meshing surface 1 (an error that, thrown, would
// abort the process from inside gmsh's threaded meshing).
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3};
Plane Surface(1) = {1};
Physical Surface("block") = {1};
