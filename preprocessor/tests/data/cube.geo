// Test geometry: the unit cube, meshed with tetrahedra. Physical groups: volume "block",
// surface "base" (z = 0).
SetFactory("OpenCASCADE");
Box(1) = {0, 0, 0, 1, 1, 1};
Physical Volume("block") = {1};
Physical Surface("base") = {5};
