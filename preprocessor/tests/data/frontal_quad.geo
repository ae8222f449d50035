// Test geometry: the unit square with gmsh's Frontal-Delaunay for quads, which crashes
// gmsh 4.8 (segmentation fault) and aims at quadrangles: Lituya refuses it before meshing.
Point(1) = {0, 0, 0};
Point(2) = {1, 0, 0};
Point(3) = {1, 1, 0};
Point(4) = {0, 1, 0};
Line(1) = {1, 2};
Line(2) = {2, 3};
Line(3) = {3, 4};
Line(4) = {4, 1};
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Physical Surface("block") = {1};
// Mesh.Algorithm = 6;  (a commented-out setting does not count)
Mesh.Algorithm = 8;
