// verification/extremes: the column of collapse.geo on a mesh graded 4x along the flow. The
// cells are `fine` wide at the upstream wall (x = 0) and 4 * fine at the end wall (x = 0.8):
// each point carries its own size and gmsh interpolates between them. The scene's cell_size
// (gmsh's largest size) must be at least 4 * fine for the grading to show.
fine = 0.0125;
coarse = 4 * fine;
// Linear in x: the size at x is fine + (coarse - fine) * x / 0.8.
s02 = fine + (coarse - fine) * 0.2 / 0.8;
Point(1) = {0, 0, 0, fine};
Point(2) = {0.2, 0, 0, s02};
Point(3) = {0.8, 0, 0, coarse};
Point(4) = {0.8, 0.3, 0, coarse};
Point(5) = {0.2, 0.3, 0, s02};
Point(6) = {0, 0.3, 0, fine};
Point(7) = {0, 0.2, 0, fine};
Point(8) = {0.2, 0.2, 0, s02};
Line(1) = {1, 2};   // bed under the column
Line(2) = {2, 8};   // gate
Line(3) = {8, 7};   // column top
Line(4) = {7, 1};   // upstream wall beside the column
Line(5) = {2, 3};   // bed beyond the gate
Line(6) = {3, 4};   // end wall
Line(7) = {4, 5};   // top
Line(8) = {5, 6};   // top
Line(9) = {6, 7};   // upstream wall above the column
Line(10) = {8, 5};  // inner line: keeps the mesh conforming to the column's corner
Curve Loop(1) = {1, 2, 3, 4};
Plane Surface(1) = {1};
Curve Loop(2) = {5, 6, 7, -10, -2};
Plane Surface(2) = {2};
Curve Loop(3) = {10, 8, 9, -3};
Plane Surface(3) = {3};
Physical Surface("column") = {1};
Physical Surface("air") = {2, 3};
Physical Curve("bed") = {1, 5};
Physical Curve("wall") = {4, 9};
Physical Curve("end") = {6};
Physical Curve("top") = {7, 8};
Physical Curve("gate") = {2};
